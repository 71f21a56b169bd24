"""Writes a fine-tuned PaddleOCR model: the base ONNX model (e.g. PP-OCRv4's detector or
recognizer from the npm registry) with the tensors that parkloc fine-tuned
(tools/detector_tuning/train.py, tools/recognizer_tuning/train.py) put in place of its own.

    python3 tools/detector_tuning/apply_tuning.py BASE.onnx TUNING.npz OUT.onnx

Every tensor NAME of the tuning file must name a Constant of the base model with the same
shape. With a NAME#columns entry beside it (int64 indices), NAME replaces only those indices
of the Constant's last axis, and its shape must be the Constant's with the last axis
len(columns). Anything else is an error, so a tuning made for another model is never half
applied.
"""
import sys

import numpy as np
import onnx
from onnx import numpy_helper

COLUMNS = "#columns"
METADATA = "__metadata__"


def fail(tuning, message):
    raise SystemExit(f"apply_tuning: {tuning}: {message}")


def read_tuning(tuning):
    """{name: (values, column indices or None)}"""
    with np.load(tuning) as f:
        entries = {k: f[k] for k in f.files if k != METADATA}
    tensors = {}
    for name, value in entries.items():
        if name.endswith(COLUMNS):
            if name[: -len(COLUMNS)] not in entries:
                fail(tuning, f"{name} has no tensor {name[: -len(COLUMNS)]} beside it")
            continue
        tensors[name] = (value, entries.get(name + COLUMNS))
    return tensors


def replaced(tuning, name, old, value, columns):
    """The Constant's new value: `value` whole, or put into `columns` of the last axis."""
    if columns is None:
        if old.shape != value.shape:
            fail(tuning, f"tensor {name} has shape {value.shape}, the model's has {old.shape}")
        return value.astype(np.float32)
    if columns.ndim != 1 or not np.issubdtype(columns.dtype, np.integer):
        fail(tuning, f"{name}{COLUMNS} must be a 1-D integer array, not {columns.dtype} "
                     f"of shape {columns.shape}")
    if old.ndim == 0:
        fail(tuning, f"tensor {name} of the model is a scalar, it has no columns")
    expected = old.shape[:-1] + (len(columns),)
    if value.shape != expected:
        fail(tuning, f"tensor {name} has shape {value.shape}, {len(columns)} columns of the "
                     f"model's {old.shape} have {expected}")
    size = old.shape[-1]
    outside = columns[(columns < 0) | (columns >= size)]
    if outside.size:
        fail(tuning, f"{name}{COLUMNS} has indices outside 0..{size - 1}: {outside.tolist()}")
    if len(np.unique(columns)) != len(columns):
        fail(tuning, f"{name}{COLUMNS} lists an index twice")
    new = old.astype(np.float32, copy=True)
    new[..., columns] = value.astype(np.float32)
    return new


def main(argv):
    if len(argv) != 4:
        raise SystemExit(__doc__.strip().split("\n\n")[1].strip())
    base, tuning, out = argv[1:]
    model = onnx.load(base)
    tensors = read_tuning(tuning)
    constants = {n.output[0]: n for n in model.graph.node if n.op_type == "Constant"}
    for name, (value, columns) in tensors.items():
        node = constants.get(name)
        if node is None:
            fail(tuning, f"tensor {name} is not in {base}")
        old = numpy_helper.to_array(node.attribute[0].t)
        new = replaced(tuning, name, old, value, columns)
        node.attribute[0].t.CopyFrom(numpy_helper.from_array(new, name))
    onnx.checker.check_model(model)
    onnx.save(model, out)
    print(f"apply_tuning: {len(tensors)} tensors of {tuning} -> {out}")


if __name__ == "__main__":
    main(sys.argv)

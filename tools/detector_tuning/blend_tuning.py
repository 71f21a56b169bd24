"""Writes a tuning part way between a base model and a fine-tuning of it: every tuned tensor
becomes base + weight * (tuned - base), the same tensors (and #columns) as the tuning.

    python3 tools/detector_tuning/blend_tuning.py BASE.onnx TUNING.npz WEIGHT OUT.npz

Why: fine-tuning on garage renders moves a PaddleOCR model away from what it read before
(ordinary scene text). Along the straight line between the two sets of weights a model keeps
most of the fine-tuning's gain on its task well before weight 1 while it still reads like the
base (weight-space ensembling of a fine-tuned and a base model, Wortsman et al., "Robust
fine-tuning of zero-shot models", 2022). WEIGHT 1 gives the tuning back, 0 the base model's own
tensors. The result is a tuning like any other: apply_tuning.py writes its model.
"""
import sys

import numpy as np
import onnx
from onnx import numpy_helper

from apply_tuning import COLUMNS, METADATA, fail, read_tuning, replaced


def blended(tuning, name, base, value, columns, weight):
    """base + weight * (value - base) over the tuned entries (all, or the listed columns), checked
    as apply_tuning checks a tuning."""
    base = base.astype(np.float32)
    mixed = base + np.float32(weight) * (replaced(tuning, name, base, value, columns) - base)
    return mixed if columns is None else mixed[..., columns]


def main(argv):
    if len(argv) != 5:
        raise SystemExit(__doc__.strip().split("\n\n")[1].strip())
    base_path, tuning, weight_text, out = argv[1:]
    try:
        weight = float(weight_text)
    except ValueError:
        fail(tuning, f"weight {weight_text!r} is not a number")
    if not 0.0 <= weight <= 1.0:
        fail(tuning, f"weight {weight} is outside 0..1")
    model = onnx.load(base_path)
    constants = {n.output[0]: n for n in model.graph.node if n.op_type == "Constant"}
    written = {}
    for name, (value, columns) in read_tuning(tuning).items():
        node = constants.get(name)
        if node is None:
            fail(tuning, f"tensor {name} is not in {base_path}")
        base = numpy_helper.to_array(node.attribute[0].t)
        written[name] = blended(tuning, name, base, value, columns, weight)
        if columns is not None:
            written[name + COLUMNS] = columns
    # The tuning's own record (repr of a dict, as the trainers write it), kept as text.
    with np.load(tuning) as f:
        source = str(f[METADATA]) if METADATA in f.files else "{}"
    blend = {"weight": weight, "base": str(base_path), "tuning": str(tuning)}
    written[METADATA] = np.array(repr({"blend": blend, "tuning_metadata": source}))
    np.savez_compressed(out, **written)
    print(f"blend_tuning: {len(written) - 1} entries of {tuning} at weight {weight} -> {out}")


if __name__ == "__main__":
    main(sys.argv)

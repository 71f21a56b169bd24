"""Writes the floor-view detector: PaddleOCR's PP-OCRv4 detector (from the npm registry) with
the tensors that parkloc fine-tuned (train.py) put in place of its own.

    python3 tools/detector_tuning/apply_tuning.py BASE.onnx TUNING.npz OUT.onnx

Every tensor of the tuning file must name a Constant of the base model with the same shape;
anything else is an error, so a tuning made for another model is never half applied.
"""
import sys

import numpy as np
import onnx
from onnx import numpy_helper


def main(argv):
    if len(argv) != 4:
        raise SystemExit(__doc__.strip().splitlines()[-3].strip())
    base, tuning, out = argv[1:]
    model = onnx.load(base)
    with np.load(tuning) as f:
        tensors = {k: f[k] for k in f.files if k != "__metadata__"}
    constants = {n.output[0]: n for n in model.graph.node if n.op_type == "Constant"}
    for name, value in tensors.items():
        node = constants.get(name)
        if node is None:
            raise SystemExit(f"apply_tuning: {tuning}: tensor {name} is not in {base}")
        old = numpy_helper.to_array(node.attribute[0].t)
        if old.shape != value.shape:
            raise SystemExit(f"apply_tuning: {tuning}: tensor {name} has shape {value.shape}, "
                             f"the model's has {old.shape}")
        node.attribute[0].t.CopyFrom(numpy_helper.from_array(value.astype(np.float32), name))
    onnx.checker.check_model(model)
    onnx.save(model, out)
    print(f"apply_tuning: {len(tensors)} tensors of {tuning} -> {out}")


if __name__ == "__main__":
    main(sys.argv)

"""tools/model_folding/fold_affine.py on small models made here, evaluated by a few lines of
numpy: every rewrite keeps the function, and an affine block before a padded convolution is
left as it was (its border taps would read zeros instead of the shift)."""
import os
import subprocess
import sys
import tempfile
import unittest

import numpy as np
import onnx
from onnx import helper, numpy_helper

SCRIPT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools",
                      "model_folding", "fold_affine.py")


def conv2d(x, w, b, pads, group):
    x = np.pad(x, ((0, 0), (0, 0), (pads[0], pads[2]), (pads[1], pads[3])))
    n, c, h, wd = x.shape
    o, cg, kh, kw = w.shape
    out = np.zeros((n, o, h - kh + 1, wd - kw + 1), np.float64)
    per = o // group
    for oc in range(o):
        g = oc // per
        for i in range(kh):
            for j in range(kw):
                patch = x[:, g * cg:(g + 1) * cg, i:i + out.shape[2], j:j + out.shape[3]]
                out[:, oc] += np.tensordot(w[oc, :, i, j], patch, axes=([0], [1]))
    return out + b.reshape(1, -1, 1, 1)


def evaluate(path, x):
    """Runs the graph of `path` on x with numpy (the ops these tests use)."""
    model = onnx.load(path)
    v = {model.graph.input[0].name: x.astype(np.float64)}
    for node in model.graph.node:
        attrs = {a.name: helper.get_attribute_value(a) for a in node.attribute}
        args = [v[i] for i in node.input]
        if node.op_type == "Constant":
            out = numpy_helper.to_array(attrs["value"]).astype(np.float64)
        elif node.op_type == "Conv":
            b = args[2] if len(args) > 2 else np.zeros(args[1].shape[0])
            out = conv2d(args[0], args[1], b, attrs.get("pads", [0, 0, 0, 0]), attrs.get("group", 1))
        elif node.op_type in ("Mul", "Add", "Div"):
            out = {"Mul": np.multiply, "Add": np.add, "Div": np.divide}[node.op_type](*args)
        elif node.op_type == "Clip":
            out = np.clip(args[0], args[1], args[2])
        elif node.op_type == "HardSigmoid":
            out = np.clip(attrs["alpha"] * args[0] + attrs["beta"], 0, 1)
        else:
            raise ValueError(node.op_type)
        v[node.output[0]] = out
    return v[model.graph.output[0].name]


class Builder:
    def __init__(self):
        self.nodes, self.count = [], 0
        self.rng = np.random.default_rng(5)

    def const(self, value):
        self.count += 1
        name = f"c{self.count}"
        self.nodes.append(helper.make_node("Constant", [], [name], value=numpy_helper.from_array(
            np.asarray(value, np.float32), name)))
        return name

    def op(self, op_type, inputs, **attrs):
        self.count += 1
        name = f"t{self.count}"
        self.nodes.append(helper.make_node(op_type, inputs, [name], **attrs))
        return name

    def conv(self, x, cin, cout, k, pad, group=1):
        w = self.const(self.rng.normal(size=(cout, cin // group, k, k)))
        b = self.const(self.rng.normal(size=cout))
        return self.op("Conv", [x, w, b], kernel_shape=[k, k], pads=[pad] * 4, group=group)

    def affine(self, x, scale, shift):
        return self.op("Add", [self.op("Mul", [self.const(scale), x]), self.const(shift)])

    def hard_swish(self, x):
        clip = self.op("Clip", [self.op("Add", [x, self.const(3.0)]), self.const(0.0),
                                self.const(6.0)])
        return self.op("Div", [self.op("Mul", [x, clip]), self.const(6.0)])

    def save(self, path, out, channels):
        graph = helper.make_graph(
            self.nodes, "small",
            [helper.make_tensor_value_info("x", onnx.TensorProto.FLOAT, [1, 2, 6, 6])],
            [helper.make_tensor_value_info(out, onnx.TensorProto.FLOAT, [1, channels, 6, 6])])
        onnx.save(helper.make_model(graph, opset_imports=[helper.make_opsetid("", 11)]), path)


class FoldAffineTest(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.TemporaryDirectory()
        self.base = os.path.join(self.dir.name, "base.onnx")
        self.out = os.path.join(self.dir.name, "out.onnx")
        self.x = np.random.default_rng(1).normal(size=(1, 2, 6, 6)) * 3

    def tearDown(self):
        self.dir.cleanup()

    def assert_folds_to(self, builder, out, channels, ops, tolerance):
        """Saves the model, folds it: these nodes remain, and the function is the same."""
        builder.save(self.base, out, channels)
        result = subprocess.run([sys.executable, SCRIPT, self.base, self.out],
                                capture_output=True, text=True)
        self.assertEqual(result.returncode, 0, result.stderr)
        folded = [n.op_type for n in onnx.load(self.out).graph.node if n.op_type != "Constant"]
        self.assertEqual(folded, ops)
        np.testing.assert_allclose(evaluate(self.out, self.x), evaluate(self.base, self.x),
                                   rtol=tolerance, atol=tolerance)

    def test_a_block_of_pp_lcnet_v3_keeps_its_function_with_fewer_nodes(self):
        b = Builder()
        # conv, affine, hard-swish, affine, then a 1x1 convolution: all of it folds.
        h = b.hard_swish(b.affine(b.conv("x", 2, 4, 3, 1), 0.9, 0.5))
        y = b.conv(b.affine(h, 0.5, -0.2), 4, 3, 1, 0)
        self.assert_folds_to(b, y, 3, ["Conv", "HardSigmoid", "Mul", "Conv"], 1e-5)

    def test_an_affine_block_before_a_padded_convolution_stays(self):
        b = Builder()
        y = b.conv(b.affine(b.op("Clip", ["x", b.const(-1.0), b.const(1.0)]), 2.0, 0.7),
                   2, 2, 3, 1, group=2)
        self.assert_folds_to(b, y, 2, ["Clip", "Mul", "Add", "Conv"], 1e-6)

    def test_a_value_read_twice_is_not_folded_into_one_reader(self):
        b = Builder()
        c = b.conv("x", 2, 2, 1, 0)
        y = b.op("Add", [b.affine(c, 1.5, 0.25), c])  # the conv output is read twice
        self.assert_folds_to(b, y, 2, ["Conv", "Mul", "Add", "Add"], 1e-6)

    def test_a_missing_model_is_one_line_naming_it(self):
        missing = os.path.join(self.dir.name, "missing.onnx")
        result = subprocess.run([sys.executable, SCRIPT, missing, self.out],
                                capture_output=True, text=True)
        self.assertNotEqual(result.returncode, 0)
        self.assertEqual(len(result.stderr.strip().splitlines()), 1, result.stderr)
        self.assertIn(missing, result.stderr)


if __name__ == "__main__":
    unittest.main()

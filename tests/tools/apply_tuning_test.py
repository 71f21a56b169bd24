"""tools/detector_tuning/apply_tuning.py on a two-node model made here: a tuning replaces the
Constant it names and nothing else, or with NAME#columns only those indices of its last axis;
a tuning for another model is refused whole."""
import os
import subprocess
import sys
import tempfile
import unittest

import numpy as np
import onnx
from onnx import numpy_helper

from tiny_onnx import tiny_model

SCRIPT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools",
                      "detector_tuning", "apply_tuning.py")


def constants(path):
    model = onnx.load(path)
    return {n.output[0]: numpy_helper.to_array(n.attribute[0].t)
            for n in model.graph.node if n.op_type == "Constant"}


def run(*args):
    return subprocess.run([sys.executable, SCRIPT, *args], capture_output=True, text=True)


class ApplyTuningTest(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.TemporaryDirectory()
        self.base = os.path.join(self.dir.name, "base.onnx")
        self.out = os.path.join(self.dir.name, "out.onnx")
        self.w, self.b = tiny_model(self.base)

    def tearDown(self):
        self.dir.cleanup()

    def tuning(self, **tensors):
        path = os.path.join(self.dir.name, "tuning.npz")
        np.savez(path, **tensors)
        return path

    def test_replaces_the_named_constant_and_keeps_the_others(self):
        new_b = np.array([2.0, 3.0], np.float16)
        result = run(self.base, self.tuning(**{"conv.b": new_b}), self.out)
        self.assertEqual(result.returncode, 0, result.stderr)
        c = constants(self.out)
        np.testing.assert_array_equal(c["conv.b"], new_b.astype(np.float32))
        self.assertEqual(c["conv.b"].dtype, np.float32)
        np.testing.assert_array_equal(c["conv.w"], self.w)

    def test_refuses_a_tensor_the_model_does_not_have(self):
        result = run(self.base, self.tuning(**{"other.w": np.zeros(2, np.float32)}), self.out)
        self.assertNotEqual(result.returncode, 0)
        self.assertIn("tensor other.w is not in", result.stderr)
        self.assertFalse(os.path.exists(self.out))

    def test_refuses_a_tensor_of_another_shape(self):
        result = run(self.base, self.tuning(**{"conv.b": np.zeros(3, np.float32)}), self.out)
        self.assertNotEqual(result.returncode, 0)
        self.assertIn("has shape (3,), the model's has (2,)", result.stderr)
        self.assertFalse(os.path.exists(self.out))

    def test_columns_replace_only_those_indices_of_the_last_axis(self):
        new_w = np.full((2, 1, 3, 2), 7.0, np.float16)
        columns = np.array([2, 0], np.int64)
        result = run(self.base, self.tuning(**{"conv.w": new_w, "conv.w#columns": columns}),
                     self.out)
        self.assertEqual(result.returncode, 0, result.stderr)
        c = constants(self.out)
        expected = self.w.copy()
        expected[..., [2, 0]] = 7.0
        np.testing.assert_array_equal(c["conv.w"], expected)
        self.assertEqual(c["conv.w"].dtype, np.float32)
        np.testing.assert_array_equal(c["conv.b"], self.b)

    def test_columns_of_a_vector(self):
        result = run(self.base, self.tuning(**{"conv.b": np.array([9.0], np.float16),
                                               "conv.b#columns": np.array([1])}), self.out)
        self.assertEqual(result.returncode, 0, result.stderr)
        np.testing.assert_array_equal(constants(self.out)["conv.b"], [0.5, 9.0])

    def test_refuses_a_column_index_out_of_range(self):
        result = run(self.base, self.tuning(**{"conv.b": np.zeros(2, np.float32),
                                               "conv.b#columns": np.array([1, 2])}), self.out)
        self.assertNotEqual(result.returncode, 0)
        self.assertIn("conv.b#columns has indices outside 0..1: [2]", result.stderr)
        self.assertFalse(os.path.exists(self.out))

    def test_refuses_columns_of_another_shape(self):
        result = run(self.base, self.tuning(**{"conv.w": np.zeros((2, 1, 2, 2), np.float32),
                                               "conv.w#columns": np.array([0, 1])}), self.out)
        self.assertNotEqual(result.returncode, 0)
        self.assertIn("tensor conv.w has shape (2, 1, 2, 2), 2 columns of the model's "
                      "(2, 1, 3, 3) have (2, 1, 3, 2)", result.stderr)
        self.assertFalse(os.path.exists(self.out))

    def test_refuses_columns_without_their_tensor(self):
        result = run(self.base, self.tuning(**{"conv.w#columns": np.array([0])}), self.out)
        self.assertNotEqual(result.returncode, 0)
        self.assertIn("conv.w#columns has no tensor conv.w beside it", result.stderr)
        self.assertFalse(os.path.exists(self.out))


if __name__ == "__main__":
    unittest.main()

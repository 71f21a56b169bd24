"""tools/detector_tuning/blend_tuning.py on a two-node model made here: every tuned tensor
becomes base + weight * (tuned - base), columns included; weight 1 gives the tuning back and 0
the base's own tensors; a weight outside 0..1 or a tuning for another model is refused."""
import os
import subprocess
import sys
import tempfile
import unittest

import numpy as np

from tiny_onnx import tiny_model

TOOLS = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools",
                     "detector_tuning")
SCRIPT = os.path.join(TOOLS, "blend_tuning.py")


def run(*args):
    return subprocess.run([sys.executable, SCRIPT, *map(str, args)], capture_output=True,
                          text=True, cwd=TOOLS)


class BlendTuningTest(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.TemporaryDirectory()
        self.base = os.path.join(self.dir.name, "base.onnx")
        self.out = os.path.join(self.dir.name, "blend.npz")
        self.w, self.b = tiny_model(self.base)
        self.tuned_b = np.array([2.5, 1.5], np.float32)
        self.tuned_w_cols = np.full((2, 1, 3, 2), 7.0, np.float32)
        self.tuning = os.path.join(self.dir.name, "tuning.npz")
        np.savez(self.tuning, **{"conv.b": self.tuned_b, "conv.w": self.tuned_w_cols,
                                 "conv.w#columns": np.array([0, 2], np.int64),
                                 "__metadata__": np.array(repr({"step": 3}))})

    def tearDown(self):
        self.dir.cleanup()

    def blended(self, weight):
        result = run(self.base, self.tuning, weight, self.out)
        self.assertEqual(result.returncode, 0, result.stderr)
        with np.load(self.out) as f:
            return {k: f[k] for k in f.files}

    def test_half_way_is_the_mean_of_base_and_tuning(self):
        t = self.blended(0.5)
        np.testing.assert_allclose(t["conv.b"], 0.5 * (self.b + self.tuned_b))
        np.testing.assert_allclose(t["conv.w"], 0.5 * (self.w[..., [0, 2]] + 7.0))
        np.testing.assert_array_equal(t["conv.w#columns"], [0, 2])
        self.assertIn("'weight': 0.5", str(t["__metadata__"]))
        self.assertIn("'step': 3", str(t["__metadata__"]))

    def test_the_ends_give_the_tuning_and_the_base(self):
        np.testing.assert_allclose(self.blended(1)["conv.b"], self.tuned_b)
        t = self.blended(0)
        np.testing.assert_allclose(t["conv.b"], self.b)
        np.testing.assert_allclose(t["conv.w"], self.w[..., [0, 2]])

    def test_refuses_a_weight_outside_zero_to_one(self):
        for weight in (1.5, -0.1, "half"):
            result = run(self.base, self.tuning, weight, self.out)
            self.assertNotEqual(result.returncode, 0)
            self.assertIn("weight", result.stderr)
        self.assertFalse(os.path.exists(self.out))

    def test_refuses_a_tuning_for_another_model(self):
        other = os.path.join(self.dir.name, "other.npz")
        np.savez(other, **{"conv.b": np.zeros(3, np.float32)})
        result = run(self.base, other, 0.5, self.out)
        self.assertNotEqual(result.returncode, 0)
        self.assertIn("has shape (3,), the model's has (2,)", result.stderr)
        self.assertFalse(os.path.exists(self.out))


if __name__ == "__main__":
    unittest.main()

"""A two-node ONNX model (a Conv with Constant weight and bias) for the tuning tools' tests."""
import numpy as np
import onnx
from onnx import helper, numpy_helper


def constant(name, value):
    return helper.make_node("Constant", [], [name], value=numpy_helper.from_array(value, name))


def tiny_model(path):
    """Writes the model to `path`; returns its Constants conv.w (2x1x3x3) and conv.b (2)."""
    w = np.arange(2 * 1 * 3 * 3, dtype=np.float32).reshape(2, 1, 3, 3)
    b = np.array([0.5, -0.5], np.float32)
    nodes = [constant("conv.w", w), constant("conv.b", b),
             helper.make_node("Conv", ["x", "conv.w", "conv.b"], ["y"], pads=[1, 1, 1, 1])]
    graph = helper.make_graph(
        nodes, "tiny", [helper.make_tensor_value_info("x", onnx.TensorProto.FLOAT, [1, 1, 4, 4])],
        [helper.make_tensor_value_info("y", onnx.TensorProto.FLOAT, [1, 2, 4, 4])])
    onnx.save(helper.make_model(graph, opset_imports=[helper.make_opsetid("", 11)]), path)
    return w, b

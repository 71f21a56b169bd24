"""The PP-OCRv4 DB detector's ONNX graph run by PyTorch, so that it can be fine-tuned.

paddle2onnx stores every weight as a Constant node. This module walks the graph node by node
(only the operators the detector uses) and turns the float constants that feed Conv,
ConvTranspose and BatchNormalization into trainable parameters, keyed by the Constant's output
name. Those names are what apply_tuning.py writes back into the ONNX file.
"""
import numpy as np
import onnx
import torch
import torch.nn.functional as F
from onnx import numpy_helper

WEIGHT_OPS = {"Conv", "ConvTranspose", "BatchNormalization"}


def _attrs(node):
    return {a.name: onnx.helper.get_attribute_value(a) for a in node.attribute}


def _safe(name):
    # ParameterDict keys may not contain dots.
    return name.replace(".", "__")


class OnnxGraph(torch.nn.Module):
    def __init__(self, model_path):
        super().__init__()
        model = onnx.load(model_path)
        graph = model.graph
        self.nodes = [n for n in graph.node if n.op_type != "Constant"]
        # Attributes decoded once, not on every forward pass of every training step.
        self.attributes = [_attrs(n) for n in self.nodes]
        self.input_name = graph.input[0].name
        self.output_name = graph.output[0].name
        constants = {}
        for n in graph.node:
            if n.op_type == "Constant":
                constants[n.output[0]] = numpy_helper.to_array(n.attribute[0].t)
        weight_names = set()
        for n in self.nodes:
            if n.op_type in WEIGHT_OPS:
                # BatchNormalization's running mean and variance (inputs 3, 4) stay fixed.
                learned = n.input[1:3] if n.op_type == "BatchNormalization" else n.input[1:]
                weight_names.update(x for x in learned if x in constants)
        # Every float constant added right after a weight op is its bias (paddle2onnx emits
        # ConvTranspose bias as a separate Add).
        producers = {o: n for n in self.nodes for o in n.output}
        for n in self.nodes:
            if n.op_type == "Add":
                src = producers.get(n.input[0])
                if src is not None and src.op_type in WEIGHT_OPS and n.input[1] in constants:
                    weight_names.add(n.input[1])
        self.params = torch.nn.ParameterDict()
        self.buffers_ = {}
        for name, value in constants.items():
            if name in weight_names and value.dtype == np.float32:
                self.params[_safe(name)] = torch.nn.Parameter(torch.from_numpy(value.copy()))
            else:
                self.buffers_[name] = torch.from_numpy(value.copy())
        # Which node consumes which weight, to select layers to train.
        self.consumer = {}
        for i, n in enumerate(self.nodes):
            for x in n.input:
                if x in weight_names:
                    self.consumer[x] = i

    def weight(self, name):
        key = _safe(name)
        if key in self.params:
            return self.params[key]
        return self.buffers_[name]

    def parameter_names(self):
        """ONNX constant names of the trainable tensors, in graph order."""
        return sorted(self.consumer, key=lambda n: self.consumer[n])

    def _value(self, env, name):
        if name in env:
            return env[name]
        return self.weight(name)

    def forward(self, x):
        env = {self.input_name: x}
        for n, a in zip(self.nodes, self.attributes):
            ins = [self._value(env, i) if i else None for i in n.input]
            op = n.op_type
            if op == "Conv":
                pads = a.get("pads", [0, 0, 0, 0])
                assert pads[0] == pads[2] and pads[1] == pads[3]
                y = F.conv2d(ins[0], ins[1], ins[2] if len(ins) > 2 else None,
                             stride=a.get("strides", [1, 1]), padding=pads[:2],
                             dilation=a.get("dilations", [1, 1]), groups=a.get("group", 1))
            elif op == "ConvTranspose":
                y = F.conv_transpose2d(ins[0], ins[1], ins[2] if len(ins) > 2 else None,
                                       stride=a.get("strides", [1, 1]),
                                       padding=a.get("pads", [0, 0, 0, 0])[:2],
                                       groups=a.get("group", 1))
            elif op == "BatchNormalization":
                # Frozen statistics (batches here are small); scale and shift still train.
                y = F.batch_norm(ins[0], ins[3], ins[4], ins[1], ins[2], training=False,
                                 eps=a.get("epsilon", 1e-5))
            elif op == "Add":
                y = ins[0] + ins[1]
            elif op == "Mul":
                y = ins[0] * ins[1]
            elif op == "Div":
                y = ins[0] / ins[1]
            elif op == "Relu":
                y = F.relu(ins[0])
            elif op == "Sigmoid":
                y = torch.sigmoid(ins[0])
            elif op == "Clip":
                y = torch.clamp(ins[0], float(ins[1]), float(ins[2]))
            elif op == "HardSigmoid":
                y = torch.clamp(ins[0] * a.get("alpha", 0.2) + a.get("beta", 0.5), 0.0, 1.0)
            elif op == "GlobalAveragePool":
                y = ins[0].mean(dim=(2, 3), keepdim=True)
            elif op == "Resize":
                assert a.get("mode", b"nearest") == b"nearest"
                scale = float(ins[2][2])
                y = F.interpolate(ins[0], scale_factor=scale, mode="nearest")
            elif op == "Concat":
                y = torch.cat(ins, dim=a["axis"])
            else:
                raise NotImplementedError(f"ONNX operator {op} ({n.name})")
            env[n.output[0]] = y
        return env[self.output_name]

"""PaddleOCR's PP-OCRv4 ONNX graphs (the DB detector and the CTC recognizer) run by PyTorch,
so that they can be fine-tuned.

    from onnx_graph import OnnxGraph
    net = OnnxGraph("third_party/models/paddleocr/ch_PP-OCRv4_rec_infer.onnx")
    features = net(x, stop="p2o.Concat.8")          # the graph input up to a node output
    probs = net(features, start="p2o.Concat.8")     # from that node output to the graph output

paddle2onnx stores every weight as a Constant node. This module walks the graph node by node
(only the operators these two graphs use, opset 9 to 11) and turns the float constants that
feed Conv, ConvTranspose, BatchNormalization and MatMul, and the constant added right after
one of them (its bias), into trainable parameters, keyed by the Constant's output name. Those
names are what apply_tuning.py writes back into the ONNX file. learn_only_columns() narrows a
parameter to some indices of its last axis (e.g. a few classes of a classifier's weight).
"""
import numpy as np
import onnx
import torch
import torch.nn.functional as F
from onnx import numpy_helper

WEIGHT_OPS = {"Conv", "ConvTranspose", "BatchNormalization", "MatMul"}

TORCH_DTYPES = {
    onnx.TensorProto.FLOAT: torch.float32,
    onnx.TensorProto.DOUBLE: torch.float64,
    onnx.TensorProto.FLOAT16: torch.float16,
    onnx.TensorProto.INT32: torch.int32,
    onnx.TensorProto.INT64: torch.int64,
    onnx.TensorProto.BOOL: torch.bool,
}


def _attrs(node):
    return {a.name: onnx.helper.get_attribute_value(a) for a in node.attribute}


def _safe(name):
    # ParameterDict keys may not contain dots.
    return name.replace(".", "__")


def _symmetric_pads(pads):
    assert pads[0] == pads[2] and pads[1] == pads[3], f"asymmetric pads {pads}"
    return pads[:2]


def _input_or_attr(ins, index, a, attr):
    """Opset 10+ passes some operands as inputs that opset 9 has as attributes."""
    if len(ins) > index and ins[index] is not None:
        return ins[index].tolist()
    return a.get(attr)


# One function per operator: (inputs, attributes, opset) -> output tensor.

def _conv(ins, a, opset):
    return F.conv2d(ins[0], ins[1], ins[2] if len(ins) > 2 else None,
                    stride=a.get("strides", [1, 1]),
                    padding=_symmetric_pads(a.get("pads", [0, 0, 0, 0])),
                    dilation=a.get("dilations", [1, 1]), groups=a.get("group", 1))


def _conv_transpose(ins, a, opset):
    return F.conv_transpose2d(ins[0], ins[1], ins[2] if len(ins) > 2 else None,
                              stride=a.get("strides", [1, 1]),
                              padding=a.get("pads", [0, 0, 0, 0])[:2],
                              groups=a.get("group", 1))


def _batch_norm(ins, a, opset):
    # Frozen statistics (batches here are small); scale and shift still train.
    return F.batch_norm(ins[0], ins[3], ins[4], ins[1], ins[2], training=False,
                        eps=a.get("epsilon", 1e-5))


def _clip(ins, a, opset):
    low = float(ins[1]) if len(ins) > 1 and ins[1] is not None else a.get("min")
    high = float(ins[2]) if len(ins) > 2 and ins[2] is not None else a.get("max")
    return torch.clamp(ins[0], low, high)


def _hard_sigmoid(ins, a, opset):
    return torch.clamp(ins[0] * a.get("alpha", 0.2) + a.get("beta", 0.5), 0.0, 1.0)


def _average_pool(ins, a, opset):
    assert not a.get("ceil_mode", 0), "AveragePool ceil_mode"
    return F.avg_pool2d(ins[0], a["kernel_shape"], stride=a.get("strides", a["kernel_shape"]),
                        padding=_symmetric_pads(a.get("pads", [0, 0, 0, 0])),
                        count_include_pad=bool(a.get("count_include_pad", 0)))


def _resize(ins, a, opset):
    assert a.get("mode", b"nearest") == b"nearest"
    return F.interpolate(ins[0], scale_factor=float(ins[2][2]), mode="nearest")


def _softmax(ins, a, opset):
    x = ins[0]
    axis = a.get("axis", -1 if opset >= 13 else 1) % x.dim()
    if opset >= 13:
        return torch.softmax(x, dim=axis)
    # Before opset 13 the input is seen as 2-D: the axes from `axis` on are one.
    flat = x.reshape(*x.shape[:axis], -1)
    return torch.softmax(flat, dim=-1).reshape(x.shape)


def _reduce_mean(ins, a, opset):
    axes = a.get("axes")
    dims = tuple(axes) if axes is not None else tuple(range(ins[0].dim()))
    return ins[0].mean(dim=dims, keepdim=bool(a.get("keepdims", 1)))


def _slice(ins, a, opset):
    x = ins[0]
    starts = _input_or_attr(ins, 1, a, "starts")
    ends = _input_or_attr(ins, 2, a, "ends")
    axes = _input_or_attr(ins, 3, a, "axes") or list(range(len(starts)))
    steps = _input_or_attr(ins, 4, a, "steps") or [1] * len(starts)
    index = [slice(None)] * x.dim()
    for axis, start, end, step in zip(axes, starts, ends, steps):
        index[axis] = slice(start, end, step)
    return x[tuple(index)]


def _squeeze(ins, a, opset):
    axes = _input_or_attr(ins, 1, a, "axes")
    if axes is None:
        return ins[0].squeeze()
    x = ins[0]
    for axis in sorted((ax % x.dim() for ax in axes), reverse=True):
        x = x.squeeze(axis)
    return x


def _reshape(ins, a, opset):
    x, shape = ins[0], ins[1].tolist()
    # A 0 keeps that dimension of the input (no allowzero in these opsets); -1 is inferred.
    shape = [x.shape[i] if s == 0 else s for i, s in enumerate(shape)]
    return x.reshape(shape)


def _onednn_product(a, b):
    """a [M, K] @ b [K, N] as oneDNN's 1x1 convolution over M positions."""
    y = torch.mkldnn_convolution(a.t().contiguous()[None, :, :, None],
                                 b.t().contiguous()[:, :, None, None], None,
                                 [0, 0], [1, 1], [1, 1], 1)
    return y[0, :, :, 0].t()


class _OneDnnMatMul(torch.autograd.Function):
    """2-D matrix product by oneDNN, forward and backward. Debian's torch has the reference
    BLAS (BLAS_INFO=generic) behind matmul, and oneDNN is about 8 times faster (the head's
    120 x 6625 classifier)."""

    @staticmethod
    def forward(ctx, a, b):
        ctx.save_for_backward(a, b)
        return _onednn_product(a, b)

    @staticmethod
    def backward(ctx, grad):
        a, b = ctx.saved_tensors
        grad_a = _onednn_product(grad, b.t()) if ctx.needs_input_grad[0] else None
        grad_b = _onednn_product(a.t(), grad) if ctx.needs_input_grad[1] else None
        return grad_a, grad_b


def _matmul(ins, a, opset):
    x, w = ins
    if (w.dim() != 2 or x.dim() < 2 or x.device.type != "cpu"
            or not torch.backends.mkldnn.is_available()):
        return torch.matmul(x, w)
    rows = x.reshape(-1, x.shape[-1])
    return _OneDnnMatMul.apply(rows, w).reshape(*x.shape[:-1], w.shape[-1])


def _transpose(ins, a, opset):
    perm = a.get("perm", list(reversed(range(ins[0].dim()))))
    return ins[0].permute(*perm)


def _shape(ins, a, opset):
    return torch.tensor(ins[0].shape, dtype=torch.int64, device=ins[0].device)


def _cast(ins, a, opset):
    return ins[0].to(TORCH_DTYPES[a["to"]])


OPERATORS = {
    "Conv": _conv,
    "ConvTranspose": _conv_transpose,
    "BatchNormalization": _batch_norm,
    "Add": lambda ins, a, opset: ins[0] + ins[1],
    "Sub": lambda ins, a, opset: ins[0] - ins[1],
    "Mul": lambda ins, a, opset: ins[0] * ins[1],
    "Div": lambda ins, a, opset: ins[0] / ins[1],
    "Pow": lambda ins, a, opset: torch.pow(ins[0], ins[1]),
    "Sqrt": lambda ins, a, opset: torch.sqrt(ins[0]),
    "MatMul": _matmul,
    "Relu": lambda ins, a, opset: F.relu(ins[0]),
    "Sigmoid": lambda ins, a, opset: torch.sigmoid(ins[0]),
    "Clip": _clip,
    "HardSigmoid": _hard_sigmoid,
    "GlobalAveragePool": lambda ins, a, opset: ins[0].mean(dim=(2, 3), keepdim=True),
    "AveragePool": _average_pool,
    "Resize": _resize,
    "Softmax": _softmax,
    "ReduceMean": _reduce_mean,
    "Concat": lambda ins, a, opset: torch.cat(ins, dim=a["axis"]),
    "Slice": _slice,
    "Squeeze": _squeeze,
    "Reshape": _reshape,
    "Transpose": _transpose,
    "Shape": _shape,
    "Cast": _cast,
}


class OnnxGraph(torch.nn.Module):
    def __init__(self, model_path):
        super().__init__()
        model = onnx.load(model_path)
        graph = model.graph
        self.opset = next((o.version for o in model.opset_import if o.domain in ("", "ai.onnx")),
                          1)
        self.nodes = [n for n in graph.node if n.op_type != "Constant"]
        # Attributes decoded once, not on every forward pass of every training step.
        self.attributes = [_attrs(n) for n in self.nodes]
        self.input_name = graph.input[0].name
        self.output_name = graph.output[0].name
        self.producer = {o: i for i, n in enumerate(self.nodes) for o in n.output}
        constants = {}
        for n in graph.node:
            if n.op_type == "Constant":
                constants[n.output[0]] = numpy_helper.to_array(n.attribute[0].t)
        weight_names = self._weight_names(constants)
        self.params = torch.nn.ParameterDict()
        self.buffers_ = {}
        for name, value in constants.items():
            if name in weight_names and value.dtype == np.float32:
                self.params[_safe(name)] = torch.nn.Parameter(torch.from_numpy(value.copy()))
            else:
                self.buffers_[name] = torch.from_numpy(value.copy())
        # Parameters narrowed by learn_only_columns: name -> indices of the last axis.
        self.column_params = torch.nn.ParameterDict()
        self.columns = {}
        # Which node consumes which weight, to select layers to train.
        self.consumer = {}
        for i, n in enumerate(self.nodes):
            for x in n.input:
                if x in weight_names:
                    self.consumer[x] = i
        self._plans = {}

    def _weight_names(self, constants):
        names = set()
        for n in self.nodes:
            if n.op_type in WEIGHT_OPS:
                # BatchNormalization's running mean and variance (inputs 3, 4) stay fixed.
                learned = n.input[1:3] if n.op_type == "BatchNormalization" else n.input[1:]
                names.update(x for x in learned if x in constants)
        # Every float constant added right after a weight op is its bias (paddle2onnx emits
        # ConvTranspose and MatMul biases as a separate Add).
        for n in self.nodes:
            if n.op_type == "Add":
                src = self.producer.get(n.input[0])
                if (src is not None and self.nodes[src].op_type in WEIGHT_OPS
                        and n.input[1] in constants):
                    names.add(n.input[1])
        return names

    def to_device(self, device):
        """Moves every tensor of the graph, trainable or not, to `device` (e.g. "cuda"); call
        it first, before choosing what learns and making an optimizer."""
        self.to(device)
        self.buffers_ = {k: v.to(device) for k, v in self.buffers_.items()}
        self.columns = {k: v.to(device) for k, v in self.columns.items()}
        return self

    def weight(self, name):
        key = _safe(name)
        if name in self.columns:
            return self.buffers_[name].index_copy(-1, self.columns[name], self.column_params[key])
        if key in self.params:
            return self.params[key]
        return self.buffers_[name]

    def parameter_names(self):
        """ONNX constant names of the trainable tensors, in graph order."""
        return sorted(self.consumer, key=lambda n: self.consumer[n])

    def learn_only_columns(self, name, columns):
        """From now on only `columns` (indices of the last axis) of weight `name` learn; the
        rest is frozen at its present value. Returns the parameter that holds those columns,
        of the tensor's shape with the last axis len(columns)."""
        key = _safe(name)
        if key not in self.params:
            raise KeyError(f"{name} is not a trainable weight of the graph")
        full = self.params[key].detach().clone()
        del self.params[key]
        columns = torch.as_tensor(columns, dtype=torch.int64, device=full.device)
        self.buffers_[name] = full
        self.columns[name] = columns
        self.column_params[key] = torch.nn.Parameter(full[..., columns].clone())
        return self.column_params[key]

    def _plan(self, start, stop):
        """Indices, in graph order, of the nodes that compute `stop` from `start`."""
        if (start, stop) in self._plans:
            return self._plans[(start, stop)]
        if stop not in self.producer and stop != start:
            raise KeyError(f"{stop} is no node output of the graph")
        needed, pending = set(), [stop]
        while pending:
            name = pending.pop()
            if name == start or not name:
                continue
            index = self.producer.get(name)
            if index is None:
                if name == self.input_name:
                    raise ValueError(f"{stop} depends on the graph input {name}, "
                                     f"not on {start} alone")
                continue  # a constant
            if index not in needed:
                needed.add(index)
                pending.extend(self.nodes[index].input)
        plan = sorted(needed)
        self._plans[(start, stop)] = plan
        return plan

    def _value(self, env, name):
        if name in env:
            return env[name]
        return self.weight(name)

    def forward(self, x, start=None, stop=None):
        """x is the tensor named `start` (default: the graph input); returns the tensor named
        `stop` (default: the graph output), running only the nodes in between."""
        start = start or self.input_name
        stop = stop or self.output_name
        env = {start: x}
        for i in self._plan(start, stop):
            n, a = self.nodes[i], self.attributes[i]
            op = OPERATORS.get(n.op_type)
            if op is None:
                raise NotImplementedError(f"ONNX operator {n.op_type} ({n.name})")
            if n.op_type == "MatMul" and n.input[1] in self.columns:
                env[n.output[0]] = self._matmul_learning_columns(env[n.input[0]], n.input[1])
                continue
            ins = [self._value(env, name) if name else None for name in n.input]
            env[n.output[0]] = op(ins, a, self.opset)
        return env[stop]

    def _matmul_learning_columns(self, x, name):
        """x @ weight(name), without the gradient of the frozen columns: the full product with
        the frozen tensor, its learning columns replaced by their own product."""
        columns = self.columns[name]
        frozen = _matmul([x, self.buffers_[name]], {}, self.opset)
        learning = _matmul([x, self.column_params[_safe(name)]], {}, self.opset)
        return frozen.index_copy(-1, columns, learning)

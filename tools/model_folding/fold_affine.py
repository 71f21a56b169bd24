"""Rewrites a PaddleOCR ONNX model (PP-LCNetV3 backbone) into an equivalent one that ONNX
Runtime runs faster on a CPU: the same function, fewer element-wise passes.

PP-LCNetV3 follows every convolution with a "learnable affine block", a scalar Mul and Add,
and exports hard-swish as four nodes (Add 3, Clip 0..6, Mul, Div 6). Each is one more pass
over a large activation and, in ONNX Runtime's blocked (NCHWc) layout, often a reorder to
plain layout and back. Three exact rewrites:

1. Conv -> Mul(scalar) [-> Add(scalar)]: folded into the convolution's weights and bias.
2. x * clip(x + 3, 0, 6) / 6: x * HardSigmoid(x; alpha 1/6, beta 1/2), the same function.
3. Mul(scalar) [-> Add(scalar)] read only by convolutions without padding: folded into their
   weights and bias (with padding the border taps would read zeros instead of the bias).

Usage: fold_affine.py IN.onnx OUT.onnx
"""
import sys

import numpy as np
import onnx
from onnx import helper, numpy_helper


class Graph:
    def __init__(self, model):
        self.model = model
        self.graph = model.graph
        self.constants = {}  # output name -> Constant node
        for node in self.graph.node:
            if node.op_type == "Constant":
                self.constants[node.output[0]] = node

    def producer(self, name):
        for node in self.graph.node:
            if name in node.output:
                return node
        return None

    def consumers(self, name):
        used = [n for n in self.graph.node if name in n.input]
        if any(o.name == name for o in self.graph.output):
            used.append(None)  # a graph output: never rewritten away
        return used

    def value(self, name):
        node = self.constants.get(name)
        return None if node is None else numpy_helper.to_array(node.attribute[0].t)

    def scalar(self, name):
        v = self.value(name)
        return None if v is None or v.size != 1 else float(v.reshape(-1)[0])

    def set_value(self, name, array):
        """A Constant of its own for `name`'s new value (a shared one is left as it was)."""
        new_name = name + "_folded"
        while new_name in self.constants:
            new_name += "_"
        node = helper.make_node("Constant", [], [new_name],
                                value=numpy_helper.from_array(array.astype(np.float32), new_name))
        self.graph.node.insert(0, node)
        self.constants[new_name] = node
        return new_name

    def remove(self, nodes):
        gone = {n.output[0] for n in nodes}  # every node here has one output
        kept = [n for n in self.graph.node if n.output[0] not in gone]
        del self.graph.node[:]
        self.graph.node.extend(kept)

    def drop_unused_constants(self):
        used = {i for n in self.graph.node for i in n.input} | {o.name for o in self.graph.output}
        self.remove([n for n in self.graph.node if n.op_type == "Constant" and n.output[0] not in used])


def scalar_affine_after(g, name):
    """The Mul(scalar) and optional Add(scalar) that alone read `name`: (nodes, scale, shift)."""
    users = g.consumers(name)
    if len(users) != 1 or users[0] is None or users[0].op_type != "Mul":
        return None
    mul = users[0]
    other = mul.input[1] if mul.input[0] == name else mul.input[0]
    scale = g.scalar(other)
    if scale is None:
        return None
    nodes, shift = [mul], 0.0
    users = g.consumers(mul.output[0])
    if len(users) == 1 and users[0] is not None and users[0].op_type == "Add":
        add = users[0]
        other = add.input[1] if add.input[0] == mul.output[0] else add.input[0]
        b = g.scalar(other)
        if b is not None:
            nodes.append(add)
            shift = b
    return nodes, scale, shift


def attribute(node, name, default):
    for a in node.attribute:
        if a.name == name:
            return helper.get_attribute_value(a)
    return default


def rename_input(g, old, new):
    for node in g.graph.node:
        for k, name in enumerate(node.input):
            if name == old:
                node.input[k] = new


def conv_weights(g, conv):
    """The convolution's constant weights and bias (zeros when it has none), or None."""
    w = g.value(conv.input[1])
    if w is None:
        return None
    bias = g.value(conv.input[2]) if len(conv.input) > 2 else np.zeros(w.shape[0], np.float32)
    return None if bias is None else (w, bias)


def set_conv_weights(g, conv, w, bias):
    conv.input[1] = g.set_value(conv.input[1], w)
    name = g.set_value(conv.input[2] if len(conv.input) > 2 else conv.output[0] + "_b", bias)
    if len(conv.input) > 2:
        conv.input[2] = name
    else:
        conv.input.append(name)


def fold_into_preceding_convs(g):
    count = 0
    # Nodes are looked up again after every rewrite: removing rebuilds the node list, and a
    # message taken from the old one no longer belongs to the graph.
    for name in [n.output[0] for n in g.graph.node if n.op_type == "Conv"]:
        conv = g.producer(name)
        found = scalar_affine_after(g, name)
        weights = conv_weights(g, conv)
        if found is None or weights is None:
            continue
        nodes, scale, shift = found
        w, bias = weights
        set_conv_weights(g, conv, w * scale, bias * scale + shift)
        rename_input(g, nodes[-1].output[0], conv.output[0])
        g.remove(nodes)
        count += 1
    return count


def clip_bounds(g, clip):
    if len(clip.input) >= 3:
        return g.scalar(clip.input[1]), g.scalar(clip.input[2])
    return attribute(clip, "min", None), attribute(clip, "max", None)


def replace_hard_swish(g):
    count = 0
    for name in [n.output[0] for n in g.graph.node if n.op_type == "Div"]:
        div = g.producer(name)
        if g.scalar(div.input[1]) != 6.0:
            continue
        mul = g.producer(div.input[0])
        if mul is None or mul.op_type != "Mul" or len(g.consumers(mul.output[0])) != 1:
            continue
        for x, c in ((mul.input[0], mul.input[1]), (mul.input[1], mul.input[0])):
            clip = g.producer(c)
            if clip is None or clip.op_type != "Clip" or len(g.consumers(c)) != 1:
                continue
            lo, hi = clip_bounds(g, clip)
            if lo is None or hi is None or float(lo) != 0.0 or float(hi) != 6.0:
                continue
            add = g.producer(clip.input[0])
            if add is None or add.op_type != "Add" or len(g.consumers(add.output[0])) != 1:
                continue
            if sorted([add.input[0] == x, g.scalar(add.input[1]) == 3.0]) != [True, True] and \
               sorted([add.input[1] == x, g.scalar(add.input[0]) == 3.0]) != [True, True]:
                continue
            gate = div.output[0] + "_hard_sigmoid"
            g.remove([add, clip, mul])
            at = [n.output[0] for n in g.graph.node].index(div.output[0])
            g.graph.node[at].CopyFrom(helper.make_node("Mul", [x, gate], [div.output[0]],
                                                       name=div.name + "_hard_swish"))
            g.graph.node.insert(at, helper.make_node("HardSigmoid", [x], [gate], alpha=1.0 / 6.0,
                                                     beta=0.5, name=div.name + "_gate"))
            count += 1
            break
    return count


def unpadded(conv):
    return attribute(conv, "auto_pad", b"NOTSET") in (b"NOTSET", b"VALID", "NOTSET", "VALID") and \
        not any(attribute(conv, "pads", []))


def foldable_conv(g, conv, source):
    """A convolution reading `source` as its data, with constant weights and bias, unpadded."""
    return conv is not None and conv.op_type == "Conv" and conv.input[0] == source and \
        unpadded(conv) and conv_weights(g, conv) is not None


def fold_into_following_convs(g):
    count = 0
    for name in [n.output[0] for n in g.graph.node if n.op_type == "Mul"]:
        mul = g.producer(name)
        if mul is None:
            continue
        x = next((i for i in mul.input if g.scalar(i) is None), None)
        found = None if x is None else scalar_affine_after(g, x)
        if found is None or found[0][0].output[0] != name:
            continue
        nodes, scale, shift = found
        out = nodes[-1].output[0]
        users = g.consumers(out)
        if not users or not all(foldable_conv(g, u, out) for u in users):
            continue
        for conv in users:
            w, bias = conv_weights(g, conv)
            set_conv_weights(g, conv, w * scale,
                             bias + shift * w.reshape(w.shape[0], -1).sum(axis=1))
            conv.input[0] = x
        g.remove(nodes)
        count += 1
    return count


def main():
    if len(sys.argv) != 3:
        raise SystemExit("usage: fold_affine.py IN.onnx OUT.onnx")
    try:
        model = onnx.load(sys.argv[1])
    except Exception as e:  # missing, unreadable or not an ONNX model
        raise SystemExit(f"fold_affine: cannot read {sys.argv[1]}: {e}")
    g = Graph(model)
    counts = (fold_into_preceding_convs(g), replace_hard_swish(g), fold_into_following_convs(g))
    g.drop_unused_constants()
    onnx.checker.check_model(model)
    onnx.save(model, sys.argv[2])
    print(f"fold_affine: {sys.argv[2]}: {counts[0]} affine blocks into the convolution before, "
          f"{counts[1]} hard-swishes, {counts[2]} affine blocks into the convolutions after")


if __name__ == "__main__":
    main()

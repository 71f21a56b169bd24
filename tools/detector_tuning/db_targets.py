"""Training targets of DB (Liao et al. 2020, section 3.3) for the probability map.

Each text quad is shrunk by D = A (1 - r^2) / L (area A, perimeter L, r = 0.4, PaddleOCR's
shrink_ratio) and filled with 1; don't-care quads (illegible, mostly occluded, vertical text
smeared onto the floor view) get weight 0 in the loss. The C++ post-processing
(src/ocr/db_postprocess.h) grows what it finds by area * 1.5 / perimeter, the inverse.
"""
import cv2
import numpy as np

SHRINK_RATIO = 0.4


def _line_intersection(p1, d1, p2, d2):
    # p1 + t d1 = p2 + s d2
    a = np.array([d1, -d2]).T
    if abs(np.linalg.det(a)) < 1e-9:
        return None
    t, _ = np.linalg.solve(a, p2 - p1)
    return p1 + t * d1


def shrink_quad(quad, ratio=SHRINK_RATIO):
    """The convex quad moved inwards by DB's offset; None when it vanishes."""
    q = np.asarray(quad, np.float64)
    area = abs(cv2.contourArea(q.astype(np.float32)))
    perimeter = cv2.arcLength(q.astype(np.float32), True)
    if area < 1.0 or perimeter < 1e-6:
        return None
    offset = area * (1.0 - ratio * ratio) / perimeter
    # Inward normals depend on the winding.
    sign = 1.0 if np.cross(q[1] - q[0], q[2] - q[1]) > 0 else -1.0
    lines = []
    for i in range(4):
        a, b = q[i], q[(i + 1) % 4]
        d = b - a
        n = np.array([-d[1], d[0]]) * sign
        norm = np.linalg.norm(n)
        if norm < 1e-9:
            return None
        lines.append((a + n / norm * offset, d))
    out = []
    for i in range(4):
        p = _line_intersection(lines[i - 1][0], lines[i - 1][1], lines[i][0], lines[i][1])
        if p is None:
            return None
        out.append(p)
    out = np.array(out)
    # A shrunk quad that turned inside out (a text line thinner than 2 D) is gone.
    if np.cross(out[1] - out[0], out[2] - out[1]) * sign <= 0:
        return None
    if abs(cv2.contourArea(out.astype(np.float32))) < 1.0:
        return None
    return out


def probability_targets(shape, care_quads, dont_care_quads):
    """(target, weight): float32 maps of `shape` (rows, cols)."""
    target = np.zeros(shape, np.float32)
    weight = np.ones(shape, np.float32)
    for q in care_quads:
        s = shrink_quad(q)
        if s is None:
            cv2.fillPoly(weight, [np.round(np.asarray(q)).astype(np.int32)], 0.0)
            continue
        cv2.fillPoly(target, [np.round(s).astype(np.int32)], 1.0)
    for q in dont_care_quads:
        cv2.fillPoly(weight, [np.round(np.asarray(q)).astype(np.int32)], 0.0)
    return target, weight

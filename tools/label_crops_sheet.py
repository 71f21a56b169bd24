"""A sheet of parking-number crops as a dataset labels them, to judge its legibility labels by eye.

    /usr/bin/python3 tools/label_crops_sheet.py OUT.jpg SEQUENCE_DIR... [--count N] [--seed S]
        [--flipped-from OTHER_SEQUENCE_DIR]

Each crop is a parking number's polygon (under half occluded, not cut by the image's edge)
rectified to 48 px tall, with its text, the label's ink_snr and the polygon's height. By default
the numbers labelled legible, drawn at random; with --flipped-from, those legible in the same
file of OTHER_SEQUENCE_DIR (the same drive labelled another way, e.g. judged on the scene) and
not legible here. RESULTS.md shows what a person reads of such sheets.
"""
import argparse
import glob
import json
import os
import random

import cv2
import numpy as np

TILE_W, CROP_H, TEXT_H, PER_ROW = 200, 48, 22, 5


def wanted(instance):
    return (instance["class"] == "parking_number" and instance.get("occluded_fraction", 0) <= 0.5
            and not instance.get("truncated"))


def candidates(sequence, flipped_from):
    for path in sorted(glob.glob(os.path.join(sequence, "labels", "*", "*.json"))):
        with open(path) as f:
            labels = json.load(f)
        others = {}
        if flipped_from:
            other = os.path.join(flipped_from, os.path.relpath(path, sequence))
            if not os.path.exists(other):
                continue
            with open(other) as f:
                others = {i["landmark_id"]: i for i in json.load(f)["instances"]}
        for inst in labels["instances"]:
            if not wanted(inst):
                continue
            if flipped_from:
                before = others.get(inst["landmark_id"])
                if inst.get("legible", True) or not before or not before.get("legible", True):
                    continue
            elif not inst.get("legible", True):
                continue
            image = path.replace(os.sep + "labels" + os.sep, os.sep + "images" + os.sep)
            yield image[: -len(".json")] + ".jpg", inst


def tile(image_path, inst):
    image = cv2.imread(image_path)
    if image is None:
        raise SystemExit(f"label_crops_sheet: cannot read {image_path}")
    p = np.array(inst["polygon"], np.float32)
    height = float(np.linalg.norm(p[3] - p[0]))
    corners = np.float32([[0, 0], [TILE_W, 0], [TILE_W, CROP_H], [0, CROP_H]])
    crop = cv2.warpPerspective(image, cv2.getPerspectiveTransform(p, corners), (TILE_W, CROP_H))
    out = np.full((CROP_H + TEXT_H, TILE_W, 3), 255, np.uint8)
    out[:CROP_H] = crop
    caption = f"{inst['text']} snr {inst.get('ink_snr', float('nan')):.0f} h{height:.0f}"
    cv2.putText(out, caption, (2, CROP_H + 16), cv2.FONT_HERSHEY_SIMPLEX, 0.45, (0, 0, 0), 1)
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__.strip().split("\n\n")[0])
    ap.add_argument("out")
    ap.add_argument("sequences", nargs="+")
    ap.add_argument("--count", type=int, default=25)
    ap.add_argument("--seed", type=int, default=3)
    ap.add_argument("--flipped-from", default="")
    a = ap.parse_args()
    if a.flipped_from and len(a.sequences) != 1:
        raise SystemExit("label_crops_sheet: --flipped-from compares one sequence")
    items = [c for s in a.sequences for c in candidates(s, a.flipped_from)]
    if not items:
        raise SystemExit("label_crops_sheet: no crop to show")
    random.Random(a.seed).shuffle(items)
    tiles = [tile(path, inst) for path, inst in items[: a.count]]
    blank = np.full_like(tiles[0], 255)
    tiles += [blank] * (-len(tiles) % PER_ROW)
    rows = [np.hstack(tiles[k:k + PER_ROW]) for k in range(0, len(tiles), PER_ROW)]
    if not cv2.imwrite(a.out, np.vstack(rows)):
        raise SystemExit(f"label_crops_sheet: cannot write {a.out}")
    print(f"label_crops_sheet: {len(items[: a.count])} of {len(items)} crops -> {a.out}")


if __name__ == "__main__":
    main()

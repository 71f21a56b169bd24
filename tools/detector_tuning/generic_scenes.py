"""Writes images of ordinary text at many sizes, the kind a detector meets outside a garage:
words, numbers and codes (generic_crops.py's) in any installed font and colour, some turned,
on plain, graded or textured grounds or on the simulator's own camera images. train.py
--keep holds a fine-tuned detector to PaddleOCR's own probability map on them, so that learning
floor views does not cost it the real world's text (the real-photo check, `parkloc eval
photos`).

    /usr/bin/python3 tools/detector_tuning/generic_scenes.py --out det/generic --count 400 \
        [--grounds datasets/default/sequences]

OUT/index.txt lists the images, one a line. No photograph is read.
"""
import argparse
import glob
import os
import random
import sys

import cv2
import numpy as np
from PIL import Image, ImageDraw, ImageFont

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..",
                                "recognizer_tuning"))
from generic_crops import colours, compress, corpus_words, latin_fonts, random_text  # noqa: E402

SIZE = 640


def ground(rng, camera_images):
    kind = rng.random()
    if camera_images and kind < 0.35:
        img = cv2.imread(rng.choice(camera_images), cv2.IMREAD_COLOR)
        if img is not None:
            y = rng.randint(0, max(0, img.shape[0] - SIZE))
            x = rng.randint(0, max(0, img.shape[1] - SIZE))
            img = img[y:y + SIZE, x:x + SIZE]
            return cv2.resize(img, (SIZE, SIZE))
    base = np.array([rng.randint(0, 255) for _ in range(3)], np.float32)
    img = np.zeros((SIZE, SIZE, 3), np.float32) + base
    if kind < 0.7:
        ramp = np.linspace(-1, 1, SIZE, dtype=np.float32)
        img += (ramp[None, :, None] * rng.uniform(0, 60) + ramp[:, None, None] * rng.uniform(0, 60))
    noise = cv2.resize(np.random.default_rng(rng.randint(0, 2**31)).normal(
        0, 1, (SIZE // 16, SIZE // 16)).astype(np.float32), (SIZE, SIZE))
    img += noise[:, :, None] * rng.uniform(0, 30)
    return np.clip(img, 0, 255).astype(np.uint8)


def scene(rng, words, fonts, camera_images):
    img = Image.fromarray(ground(rng, camera_images)[:, :, ::-1].copy())
    for _ in range(rng.randint(2, 9)):
        text = random_text(rng, words)
        font = ImageFont.truetype(rng.choice(fonts), rng.choice([14, 18, 24, 32, 44, 60, 80]))
        left, top, right, bottom = font.getbbox(text)
        w, h = right - left + 8, bottom - top + 8
        if w <= 8 or h <= 8 or w >= SIZE:
            continue
        fg, bg = colours(rng)
        layer = Image.new("RGBA", (w, h), (0, 0, 0, 0))
        draw = ImageDraw.Draw(layer)
        if rng.random() < 0.4:  # on a sign of its own colour
            draw.rectangle([0, 0, w - 1, h - 1], fill=bg + (255,))
        draw.text((4 - left, 4 - top), text, font=font, fill=fg + (255,))
        if rng.random() < 0.3:
            layer = layer.rotate(rng.uniform(-30, 30), expand=True, resample=Image.BICUBIC)
        x = rng.randint(0, max(0, SIZE - layer.width))
        y = rng.randint(0, max(0, SIZE - layer.height))
        img.paste(layer, (x, y), layer)
    out = np.asarray(img)[:, :, ::-1].copy()
    if rng.random() < 0.4:
        out = cv2.GaussianBlur(out, (0, 0), rng.uniform(0.4, 1.5))
    if rng.random() < 0.5:
        out = compress(out, rng.randint(40, 95))
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--out", required=True)
    ap.add_argument("--count", type=int, default=400)
    ap.add_argument("--grounds", default="",
                    help="a folder of sequences whose camera images serve as grounds")
    ap.add_argument("--seed", type=int, default=1)
    args = ap.parse_args()

    rng = random.Random(args.seed)
    words, fonts = corpus_words(), latin_fonts()
    camera_images = sorted(glob.glob(os.path.join(args.grounds, "*", "images", "*", "*.jpg"))) \
        if args.grounds else []
    os.makedirs(args.out, exist_ok=True)
    names = []
    for i in range(args.count):
        name = f"s{i:05d}.png"
        cv2.imwrite(os.path.join(args.out, name), scene(rng, words, fonts, camera_images))
        names.append(name + "\n")
    with open(os.path.join(args.out, "index.txt"), "w") as f:
        f.writelines(names)
    print(f"wrote {len(names)} scenes to {args.out} ({len(camera_images)} camera images as grounds)")


if __name__ == "__main__":
    main()

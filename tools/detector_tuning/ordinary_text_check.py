"""Writes labelled images of ordinary text in the folder layout `parkloc eval photos` reads, to
see how a detector meant for garage floors does on the text of the world outside without
looking at the real photographs (which are measured, never tuned on):

    /usr/bin/python3 tools/detector_tuning/ordinary_text_check.py --out det/ordinary
    parkloc eval photos det/ordinary/small_words
    parkloc eval photos det/ordinary/lines

Four sets, each its own folder with labels.tsv: `small_words` (single words 14-22 px tall),
`lines` (lines of 2-5 words, 14-22 px, three heights apart), `dense_lines` (the same, 1.35
heights apart, as a page or a sign of several lines), `large_words` (single words 18-60 px).
Dark text on a light ground and light on dark alike, in every installed Latin font
(generic_crops.py's words and fonts); a word is scored as `parkloc eval photos` scores a
photo's.
"""
import argparse
import os
import random
import sys

import cv2
import numpy as np
from PIL import Image, ImageDraw, ImageFont

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..",
                                "recognizer_tuning"))
from generic_crops import corpus_words, latin_fonts  # noqa: E402

WIDTH, HEIGHT = 800, 600

# name: (text heights in px, words per line, line pitch in heights)
SETS = {
    "small_words": ([14, 18, 22], (1, 1), 3.0),
    "lines": ([14, 18, 22], (2, 5), 3.0),
    "dense_lines": ([14, 18, 22], (2, 5), 1.35),
    "large_words": ([18, 24, 32, 44, 60], (1, 1), 2.5),
}


def image_of_text(rng, words, fonts, heights, per_line, pitch):
    """A ground of one grey, lines of text in one font and height down it; the words drawn."""
    ink, ground = rng.randint(0, 60), rng.randint(190, 255)
    if rng.random() < 0.5:
        ink, ground = ground, ink
    img = Image.new("RGB", (WIDTH, HEIGHT), (ground,) * 3)
    draw = ImageDraw.Draw(img)
    size = rng.choice(heights)
    font = ImageFont.truetype(rng.choice(fonts), size)
    drawn, y = [], 20
    while y < HEIGHT - size - 20:
        line = [rng.choice(words) for _ in range(rng.randint(*per_line))]
        draw.text((rng.randint(10, 200), y), " ".join(line), font=font, fill=(ink,) * 3)
        drawn += line
        y += int(size * pitch)
    bgr = np.asarray(img)[:, :, ::-1].astype(np.float32)
    noise = np.random.default_rng(rng.randint(0, 2**31)).normal(0, 4, bgr.shape)
    return np.clip(bgr + noise, 0, 255).astype(np.uint8), drawn


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--out", required=True)
    ap.add_argument("--count", type=int, default=30, help="images per set")
    ap.add_argument("--seed", type=int, default=1)
    args = ap.parse_args()

    rng = random.Random(args.seed)
    fonts = latin_fonts()
    # Letters and digits only, three or more: what the scoring counts as one word.
    words = ["".join(c for c in w if c.isalnum()) for w in corpus_words()]
    words = [w for w in words if len(w) >= 3]
    for name, (heights, per_line, pitch) in SETS.items():
        folder = os.path.join(args.out, name)
        os.makedirs(folder, exist_ok=True)
        rows = []
        for i in range(args.count):
            img, drawn = image_of_text(rng, words, fonts, heights, per_line, pitch)
            file = f"{name}_{i:03d}.png"
            cv2.imwrite(os.path.join(folder, file), img)
            rows.append(f"{file}\tordinary_text_check.py\t{file}\t{'|'.join(drawn)}\n")
        with open(os.path.join(folder, "labels.tsv"), "w") as f:
            f.writelines(rows)
        print(f"wrote {args.count} images to {folder}")


if __name__ == "__main__":
    main()

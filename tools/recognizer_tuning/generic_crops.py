"""Writes crops of ordinary text, the kind a recognizer meets outside a garage: words of English
prose, numbers, codes, phone numbers and web addresses, in any installed font, case and colour,
on plain, graded or noisy grounds, slightly turned, blurred and compressed. train.py --keep
holds the tuned recognizer to PaddleOCR's own reading of them, so that learning the garage's
text does not cost it the real world's (the real-photo check, `parkloc eval photos`).

    /usr/bin/python3 tools/recognizer_tuning/generic_crops.py --out data/rec_generic \
        --count 4000 --dict third_party/models/ppocr_keys_v1.txt

OUT/index.tsv lists `CROP.png<TAB>TEXT<TAB>other`, as `parkloc train recognizer-data` writes;
the words come from the licence texts under /usr/share/common-licenses, the fonts from
/usr/share/fonts. No photograph is read.
"""
import argparse
import glob
import os
import random
import re

import cv2
import numpy as np
from PIL import Image, ImageDraw, ImageFont

HEIGHT = 48


def corpus_words():
    words = []
    for path in sorted(glob.glob("/usr/share/common-licenses/*")):
        if os.path.isfile(path):
            with open(path, encoding="utf-8", errors="ignore") as f:
                words += re.findall(r"[A-Za-z][A-Za-z'&.-]{1,14}", f.read())
    if not words:
        raise SystemExit("generic_crops.py: no words under /usr/share/common-licenses")
    return words


def latin_fonts():
    fonts = [p for p in glob.glob("/usr/share/fonts/**/*", recursive=True)
             if p.lower().endswith((".ttf", ".otf"))]
    usable = []
    for path in sorted(fonts):
        try:
            font = ImageFont.truetype(path, 32)
            if font.getbbox("Ag5")[2] > 0:
                usable.append(path)
        except OSError:
            continue
    if not usable:
        raise SystemExit("generic_crops.py: no TrueType or OpenType font under /usr/share/fonts")
    return usable


def random_text(rng, words):
    kind = rng.random()
    if kind < 0.55:
        text = " ".join(rng.choice(words) for _ in range(rng.choice([1, 1, 1, 2, 2, 3])))
        case = rng.random()
        if case < 0.3:
            text = text.upper()
        elif case < 0.5:
            text = text.title()
        return text
    if kind < 0.7:
        return str(rng.randint(0, 10 ** rng.randint(1, 5)))
    if kind < 0.8:
        return f"{rng.randint(200, 999)}-{rng.randint(200, 999)}-{rng.randint(1000, 9999)}"
    if kind < 0.9:
        letters = "ABCDEFGHJKLMNPRSTUVWXYZ"
        return "".join(rng.choice(letters + "0123456789") for _ in range(rng.randint(3, 8)))
    return f"www.{rng.choice(words).lower()}.{rng.choice(['com', 'org', 'net', 'de', 'fr'])}"


def luminance(c):
    return 0.299 * c[0] + 0.587 * c[1] + 0.114 * c[2]


def colours(rng):
    while True:
        fg = tuple(rng.randint(0, 255) for _ in range(3))
        bg = tuple(rng.randint(0, 255) for _ in range(3))
        if abs(luminance(fg) - luminance(bg)) > 70:
            return fg, bg


def compress(img, quality):
    """A JPEG round trip at `quality`: the blocks of a camera's or a web page's codec."""
    ok, buf = cv2.imencode(".jpg", img, [cv2.IMWRITE_JPEG_QUALITY, quality])
    return cv2.imdecode(buf, cv2.IMREAD_COLOR)


def render(rng, text, font_path):
    size = rng.randint(26, 44)
    font = ImageFont.truetype(font_path, size)
    left, top, right, bottom = font.getbbox(text)
    if right - left <= 0 or bottom - top <= 0:
        return None
    pad = size // 2
    w, h = right - left + 2 * pad, bottom - top + 2 * pad
    fg, bg = colours(rng)
    canvas = np.zeros((h, w, 3), np.float32) + np.array(bg, np.float32)
    ground = rng.random()
    if ground < 0.3:  # a gradient, as light falls across a sign
        ramp = np.linspace(-1, 1, w, dtype=np.float32)[None, :, None]
        canvas += ramp * rng.uniform(10, 50)
    elif ground < 0.5:  # texture: grain at a few scales
        noise = cv2.resize(np.random.default_rng(rng.randint(0, 2**31)).normal(
            0, 1, (max(2, h // 8), max(2, w // 8), 1)).astype(np.float32), (w, h))
        canvas += noise[:, :, None] * rng.uniform(5, 25)
    image = Image.fromarray(np.clip(canvas, 0, 255).astype(np.uint8))
    ImageDraw.Draw(image).text((pad - left, pad - top), text, font=font, fill=fg)
    img = np.asarray(image)[:, :, ::-1].copy()  # RGB -> BGR
    # A slight turn and shear, as a sign seen a little from the side.
    angle, shear = rng.uniform(-3, 3), rng.uniform(-0.15, 0.15)
    m = cv2.getRotationMatrix2D((w / 2, h / 2), angle, 1.0)
    m[0, 1] += shear
    img = cv2.warpAffine(img, m, (w, h), borderMode=cv2.BORDER_REPLICATE)
    # Tight to the text with a little margin, as a detector's box is.
    margin = int(size * rng.uniform(0.1, 0.35))
    y0, y1 = max(0, pad - margin), min(h, pad + (bottom - top) + margin)
    x0, x1 = max(0, pad - margin), min(w, pad + (right - left) + margin)
    img = img[y0:y1, x0:x1]
    scale = HEIGHT / img.shape[0]
    img = cv2.resize(img, (max(8, int(round(img.shape[1] * scale))), HEIGHT),
                     interpolation=cv2.INTER_AREA)
    if rng.random() < 0.5:
        img = cv2.GaussianBlur(img, (0, 0), rng.uniform(0.4, 1.4))
    if rng.random() < 0.5:
        noise = np.random.default_rng(rng.randint(0, 2**31)).normal(0, rng.uniform(2, 10), img.shape)
        img = np.clip(img.astype(np.float32) + noise, 0, 255).astype(np.uint8)
    if rng.random() < 0.5:
        img = compress(img, rng.randint(30, 90))
    return img


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--out", required=True)
    ap.add_argument("--count", type=int, default=4000)
    ap.add_argument("--dict", required=True, help="the recognizer's character list")
    ap.add_argument("--max-width", type=int, default=480, help="crops wider are left out")
    ap.add_argument("--seed", type=int, default=1)
    args = ap.parse_args()

    rng = random.Random(args.seed)
    with open(args.dict, encoding="utf-8") as f:
        known = {line.rstrip("\n").rstrip("\r") for line in f} | {" "}
    words = [w for w in corpus_words() if all(ch in known for ch in w)]
    fonts = latin_fonts()
    os.makedirs(args.out, exist_ok=True)
    lines = []
    while len(lines) < args.count:
        text = random_text(rng, words)
        if not all(ch in known for ch in text):
            continue
        img = render(rng, text, rng.choice(fonts))
        if img is None or img.shape[1] > args.max_width:
            continue
        name = f"g{len(lines):05d}.png"
        cv2.imwrite(os.path.join(args.out, name), img)
        lines.append(f"{name}\t{text}\tother\n")
    with open(os.path.join(args.out, "index.tsv"), "w", encoding="utf-8") as f:
        f.writelines(lines)
    print(f"wrote {len(lines)} crops in {len(fonts)} fonts to {args.out}")


if __name__ == "__main__":
    main()

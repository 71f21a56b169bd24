"""Copies crop folders of `parkloc train recognizer-data` with every crop re-encoded as JPEG,
so that a training set fits what travels to a lent GPU machine (64 MiB with the repository;
quality 92 makes a training set of 11,600 crops 22 MB instead of 125 MB). train_whole.py reads
either.

    /usr/bin/python3 tools/recognizer_tuning/pack_crops.py --quality 92 --out .gpu \
        /work/data/rec_train /work/data/rec_fonts_train /work/data/rec_val /work/data/rec_fonts_val

Each FOLDER becomes OUT/<its name>/index.tsv with OUT/<its name>/crops/*.jpg, the index's
other columns kept.
"""
import argparse
import os

import cv2

from crop_index import crops_of


def pack(folder, out_root, quality):
    out = os.path.join(out_root, os.path.basename(os.path.normpath(folder)))
    lines = []
    for rel, image, fields in crops_of(folder, "pack_crops.py"):
        jpeg = os.path.splitext(rel)[0] + ".jpg"
        os.makedirs(os.path.dirname(os.path.join(out, jpeg)), exist_ok=True)
        if not cv2.imwrite(os.path.join(out, jpeg), image, [cv2.IMWRITE_JPEG_QUALITY, quality]):
            raise SystemExit(f"pack_crops.py: cannot write {os.path.join(out, jpeg)}")
        lines.append("\t".join([jpeg] + fields[1:]))
    with open(os.path.join(out, "index.tsv"), "w", encoding="utf-8") as f:
        f.write("\n".join(lines) + "\n")
    print(f"{folder}: {len(lines)} crops -> {out}")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("folders", nargs="+")
    ap.add_argument("--out", required=True)
    ap.add_argument("--quality", type=int, default=92)
    args = ap.parse_args()
    for folder in args.folders:
        pack(folder, args.out, args.quality)


if __name__ == "__main__":
    main()

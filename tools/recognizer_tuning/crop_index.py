"""The crop folders that `parkloc train recognizer-data` writes: FOLDER/index.tsv, one line
`CROP<TAB>TEXT<TAB>CLASS` a crop, CROP relative to FOLDER (any image file)."""
import os

import cv2


def crops_of(folder, tool):
    """(image path relative to FOLDER, BGR image, the line's fields) for each line of
    FOLDER/index.tsv; `tool` names the caller in the one-line errors."""
    index = os.path.join(folder, "index.tsv")
    if not os.path.isfile(index):
        raise SystemExit(f"{tool}: {index} not found (crops of parkloc train recognizer-data)")
    with open(index, encoding="utf-8") as f:
        for line in f:
            line = line.rstrip("\n")
            if not line:
                continue
            fields = line.split("\t")
            if len(fields) < 2:
                raise SystemExit(f"{tool}: {index}: line without a text: {line!r}")
            image = cv2.imread(os.path.join(folder, fields[0]), cv2.IMREAD_COLOR)
            if image is None:
                raise SystemExit(f"{tool}: {fields[0]} in {folder} is no image")
            yield fields[0], image, fields

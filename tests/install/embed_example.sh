#!/bin/sh
# The installed package as another project sees it: `cmake --install` into an empty prefix,
# examples/embed configured and built against that prefix alone, and run on a rendered drive
# written as one video per camera. Passes when the example found the installed models, printed
# a pose for most frame sets, and every pose lies within 0.2 m of the drive's truth.
# Usage: embed_example.sh BUILD_DIR SOURCE_DIR PARKLOC WORK_DIR CMAKE
set -eu
build=$1 source=$2 parkloc=$3 work=$4 cmake=$5
frames=12

rm -rf "$work"
mkdir -p "$work"
"$cmake" --install "$build" --prefix "$work/prefix" >"$work/install.log"
"$parkloc" simulate --scenario "$source/data/scenarios/default.yaml" --split test \
  --max-sequences 1 --max-frames $frames --out "$work/render" --quiet >/dev/null
"$parkloc" convert "$(ls -d "$work"/render/sequences/*)" --out "$work/drive" >/dev/null
"$cmake" -S "$source/examples/embed" -B "$work/build" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_PREFIX_PATH="$work/prefix" >"$work/configure.log"
"$cmake" --build "$work/build" >"$work/build.log"
env -u PARKLOC_MODEL_DIR "$work/build/embed" "$work/drive" >"$work/poses.tum" 2>"$work/stderr.log"

grep -qx "models: $work/prefix/share/parkloc/models" "$work/stderr.log" ||
  { echo "the example did not use the installed models:"; cat "$work/stderr.log"; exit 1; }
# Each estimate against the truth at its time (poses.tum: t x y z qx qy qz qw).
awk -v frames=$frames '
  NR == FNR { if ($1 !~ /^#/) truth[sprintf("%.6f", $1)] = $2 " " $3; next }
  {
    key = sprintf("%.6f", $1)
    if (!(key in truth)) { print "no truth at " key; bad = 1; next }
    split(truth[key], p, " ")
    e = sqrt(($2 - p[1]) ^ 2 + ($3 - p[2]) ^ 2)
    if (e > max) max = e
    n++
  }
  END {
    printf "%d of %d frame sets with a pose, max position error %.3f m\n", n, frames, max
    exit (bad || n < frames / 2 || max > 0.2)
  }' "$work/drive/poses.tum" "$work/poses.tum"

#!/usr/bin/env bash
# Runs the libFuzzer targets one after the other and prints a summary line per target.
#   fuzz/run.sh BUILD_DIR SECONDS [TARGET...]      (targets: calibration map tum ...)
# FUZZ_RUNS=N runs each target for N executions instead of SECONDS (0 = no limit).
# New corpus inputs go to BUILD_DIR/fuzz-work/corpus/<target> (the committed seeds in
# fuzz/corpus/<target> stay as they are); crashes, leaks and timeouts are written to
# BUILD_DIR/fuzz-work/artifacts/<target>/; the full log is BUILD_DIR/fuzz-work/<target>.log.
# Exit status 1 when any target found a problem.
set -uo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
build="${1:?usage: fuzz/run.sh BUILD_DIR SECONDS [TARGET...]}"
seconds="${2:?usage: fuzz/run.sh BUILD_DIR SECONDS [TARGET...]}"
shift 2
targets=("$@")
[ ${#targets[@]} -eq 0 ] && targets=(calibration map tum odometry video_timestamps labels image scenario config)
runs="${FUZZ_RUNS:-0}"
work="$build/fuzz-work"
mkdir -p "$work"

dict_of() {
  case "$1" in
    calibration | scenario | config) echo "$here/yaml.dict" ;;
    map | labels) echo "$here/geojson.dict" ;;
  esac
}

status=0
printf '%-12s %12s %8s %7s %7s %7s  %s\n' target executions exec/s cov ft corpus result
for t in "${targets[@]}"; do
  bin="$build/fuzz/fuzz_$t"
  if [ ! -x "$bin" ]; then
    printf '%-12s not built (%s)\n' "$t" "$bin"
    continue
  fi
  mkdir -p "$work/corpus/$t" "$work/artifacts/$t"
  # -max_total_time=0: no time limit (with FUZZ_RUNS); -timeout: an input taking 10 s is a hang.
  args=(-max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -print_final_stats=1
        -artifact_prefix="$work/artifacts/$t/")
  [ "$runs" != 0 ] && args+=(-runs="$runs")
  dict="$(dict_of "$t")"
  [ -n "$dict" ] && args+=(-dict="$dict")
  # libjpeg and libpng print a warning per corrupt frame; keep the log readable.
  [ "$t" = image ] && args+=(-close_fd_mask=2)
  log="$work/$t.log"
  "$bin" "${args[@]}" "$work/corpus/$t" "$here/corpus/$t" >"$log" 2>&1
  rc=$?
  execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  rate=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log" | tail -1)
  cov=$(grep -o 'cov: [0-9]*' "$log" | tail -1 | cut -d' ' -f2)
  ft=$(grep -o 'ft: [0-9]*' "$log" | tail -1 | cut -d' ' -f2)
  corpus=$(grep -o 'corp: [0-9]*' "$log" | tail -1 | cut -d' ' -f2)
  result=ok
  if [ $rc -ne 0 ]; then
    result="FAILED (rc $rc): $(grep -m1 -E 'ERROR|SUMMARY|contract violated|Deadly' "$log" | head -c 160) - see $log"
    status=1
  fi
  printf '%-12s %12s %8s %7s %7s %7s  %s\n' "$t" "${execs:-?}" "${rate:-?}" "${cov:-?}" \
    "${ft:-?}" "${corpus:-?}" "$result"
done
exit $status

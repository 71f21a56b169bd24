#!/usr/bin/env python3
"""Fault-injection and consistency measurements for docs/RELIABILITY.md.

For every sequence and every fault, runs `parkloc run --inject SPEC` and
`parkloc check consistency`, then prints a markdown table per fault (figures over the
sequences: mean and max position error, frames answered, NEES inside the bound, integrity
misses).

  scripts/reliability_faults.py --parkloc build-rel/apps/parkloc/parkloc \
      --sequences /tmp/rel-data/sequences --out /tmp/rel-runs [--oracle] [--faults NAME,...]
"""
import argparse
import json
import os
import re
import subprocess
import sys

# name, spec, what the issue asks for
FAULTS = [
    ("none", "", "baseline, no fault"),
    ("dark", "dark:front:5-10", "front camera dark for 5 s"),
    ("freeze", "freeze:left:5-10", "left camera frozen for 5 s"),
    ("missing", "missing:rear", "rear camera missing for the whole drive"),
    ("drop", "drop:0.1", "10 % of frame sets dropped"),
    ("corrupt", "corrupt:0.05", "5 % of images corrupt JPEG"),
    ("odo-dropout", "odo-dropout:5-10", "no odometry for 5 s"),
    ("yaw-bias", "yaw-bias:0.02", "yaw rate biased by 0.02 rad/s (1.15 deg/s)"),
    ("spoof", "spoof:B1-105@B1-112", "sign B1-112 shows B1-105"),
    ("kidnap", "kidnap:6", "vehicle jumps 20 m at t = 6 s"),
    ("all-cameras-dark", "dark:front:5-10,dark:rear:5-10,dark:left:5-10,dark:right:5-10",
     "every camera dark for 5 s (dead reckoning only)"),
]


def run(cmd):
    p = subprocess.run(cmd, capture_output=True, text=True)
    if p.returncode != 0:
        raise RuntimeError(f"{' '.join(cmd)} failed ({p.returncode}):\n{p.stderr[-2000:]}")
    return p.stdout


def frames_with_warnings(frames_path, prefix="fault:"):
    n = 0
    statuses = {}
    with open(frames_path) as f:
        for line in f:
            j = json.loads(line)
            statuses[j["status"]] = statuses.get(j["status"], 0) + 1
            if any(w.startswith(prefix) for w in j.get("warnings", [])):
                n += 1
    return n, statuses


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--parkloc", required=True)
    ap.add_argument("--sequences", required=True)
    ap.add_argument("--out", required=True)
    ap.add_argument("--oracle", action="store_true")
    ap.add_argument("--faults", default="")
    ap.add_argument("--extra", default="", help="extra arguments for parkloc run")
    a = ap.parse_args()
    wanted = set(a.faults.split(",")) if a.faults else None
    sequences = sorted(d for d in os.listdir(a.sequences)
                       if os.path.isfile(os.path.join(a.sequences, d, "poses.tum")))
    rows = []
    for name, spec, what in FAULTS:
        if wanted and name not in wanted:
            continue
        per_seq = []
        for seq in sequences:
            seq_dir = os.path.join(a.sequences, seq)
            out = os.path.join(a.out, name, seq)
            cmd = [a.parkloc, "run", seq_dir, "--out", out, "--quiet"]
            if a.oracle:
                cmd.append("--oracle")
            if spec:
                cmd += ["--inject", spec]
            if a.extra:
                cmd += a.extra.split()
            text = run(cmd)
            skipped = re.search(r"(\d+) frame sets skipped", text)
            summary_path = os.path.join(out, "consistency.json")
            run([a.parkloc, "check", "consistency", out, "--truth",
                 os.path.join(seq_dir, "poses.tum"), "--json", summary_path,
                 "--per-frame", os.path.join(out, "consistency.csv")])
            with open(summary_path) as f:
                s = json.load(f)
            s["fault_frames"], s["statuses"] = frames_with_warnings(
                os.path.join(out, "frames.jsonl"))
            s["skipped"] = int(skipped.group(1)) if skipped else 0
            per_seq.append(s)
            print(f"{name:18s} {seq}: mean {s['mean_position_error_m']:.3f} m max "
                  f"{s['max_position_error_m']:.3f} m  NEES in {100 * s['fraction_inside']:.1f} %"
                  f"  missed {s['missed_detections']}  unanswered {s['frames_unanswered']}"
                  f"  statuses {s['statuses']}  fault frames {s['fault_frames']}"
                  f"  skipped {s['skipped']}", file=sys.stderr)
        rows.append((name, spec, what, per_seq))

    mode = "oracle OCR" if a.oracle else "PP-OCR"
    print(f"| fault | spec | frames (skipped) | answered | lost | mean error m | max error m "
          f"| NEES inside % | alerts | missed | ({mode}) |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    for name, spec, what, per_seq in rows:
        frames = sum(s["frames"] for s in per_seq)
        skipped = sum(s["skipped"] for s in per_seq)
        unanswered = sum(s["frames_unanswered"] for s in per_seq)
        lost = sum(s["statuses"].get("lost", 0) for s in per_seq)
        with_truth = sum(s["frames_with_pose_and_truth"] for s in per_seq)
        mean = sum(s["mean_position_error_m"] * s["frames_with_pose_and_truth"]
                   for s in per_seq) / max(1, with_truth)
        worst = max(s["max_position_error_m"] for s in per_seq)
        inside = sum(s["inside_bound"] for s in per_seq) / max(1, with_truth)
        alerts = sum(s["alerts"] for s in per_seq)
        missed = sum(s["missed_detections"] for s in per_seq)
        print(f"| {name} | `{spec or '-'}` | {frames} ({skipped}) | "
              f"{frames - unanswered}/{frames} | {lost} | {mean:.3f} | {worst:.3f} | "
              f"{100 * inside:.1f} | {alerts} | {missed} | {what} |")


if __name__ == "__main__":
    main()

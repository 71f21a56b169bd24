"""Fine-tunes every weight of PP-OCRv4's CTC recognizer on crops written by the C++ exporter
(parkloc train recognizer-data), each batch changed at random by augment.py, on a GPU when
there is one (the whole network must run forward and backward on every step, so nothing is
cached as train.py caches the frozen part's output).

    python3 tools/recognizer_tuning/train_whole.py \
        --base BASE.onnx --dict third_party/models/ppocr_keys_v1.txt \
        --train /work/data/rec_train [MORE...] --val /work/data/rec_val [MORE...] \
        --out models/recognizer_tuning.npz --device cuda --seconds 300

BASE is PaddleOCR's recognizer, or that with a tuning already applied (apply_tuning.py):
training goes on from its weights, and the L2 pull (--pull) holds every weight near them. Of the
classifier only the blank's and --alphabet's columns learn, as in train.py; batch-norm
statistics stay frozen. The run lasts about --seconds of training: after a few steps it knows
its speed and sets the number of steps, over which the learning rate falls along a cosine. It
checks the val crops every --val-every steps, and writes the tensors of the check with the best
val exact match (blank + alphabet) to --out, in train.py's format, which
tools/detector_tuning/apply_tuning.py puts into PaddleOCR's model at set-up.
"""
import argparse
import math
import os
import random
import sys
import time

import numpy as np
import torch

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import train as tail  # noqa: E402  (train.py: data, CTC and the tuning file's format)
from augment import augment  # noqa: E402
from crop_index import crops_of  # noqa: E402

from onnx_graph import OnnxGraph  # noqa: E402  (put on the path by train.py)


def load_crops(folders):
    """[(BGR crop, text, class)] of every FOLDER/index.tsv; a crop may be any image file."""
    samples = []
    for folder in folders:
        for rel, image, fields in crops_of(folder, "train_whole.py"):
            if image.shape[0] != tail.HEIGHT:
                raise SystemExit(f"train_whole.py: {rel} in {folder} is not {tail.HEIGHT} px tall")
            samples.append((image, fields[1], fields[2] if len(fields) > 2 else ""))
    if not samples:
        raise SystemExit(f"train_whole.py: no crops in {folders}")
    return samples


class Crops:
    """A split on the device: crops grouped by the input width they are fed at (the crop's
    width rounded up to 8 px, at least train.INPUT_WIDTH), as normalised tensors."""

    def __init__(self, samples, class_of, device):
        self.texts = [t for _, t, _ in samples]
        self.classes = [c for _, _, c in samples]
        self.targets = [tail.encode(t, class_of) for t in self.texts]
        self.widths = [img.shape[1] for img, _, _ in samples]
        groups = {}
        for i, (img, _, _) in enumerate(samples):
            width = tail.padded_width(img.shape[1])
            if tail.ctc_min_steps(self.targets[i]) <= width // tail.STEP:
                groups.setdefault(width, []).append(i)
        self.groups = {}  # input width -> (sample indices, [n, 3, 48, width] tensor)
        for width, indices in groups.items():
            x = np.stack([tail.normalise(samples[i][0], width) for i in indices])
            self.groups[width] = (indices, torch.from_numpy(x).to(device))
        self.feasible = sum(len(v[0]) for v in self.groups.values())

    def __len__(self):
        return len(self.texts)

    def batches(self, size, rng=None):
        """[(width, positions within that width's group)], shuffled when rng is given."""
        out = []
        for width, (indices, _) in self.groups.items():
            order = list(range(len(indices)))
            if rng:
                rng.shuffle(order)
            out += [(width, order[k: k + size]) for k in range(0, len(order), size)]
        if rng:
            rng.shuffle(out)
        return out

    def batch(self, width, positions):
        indices, x = self.groups[width]
        chosen = [indices[p] for p in positions]
        rows = torch.as_tensor(positions, device=x.device)
        return (x.index_select(0, rows), [self.widths[i] for i in chosen],
                [self.targets[i] for i in chosen], chosen)


def evaluate(net, crops, logits_at, characters, columns, batch):
    """Exact match over all crops (those too narrow for their text count as misread), per
    class too, decoding over blank + alphabet; and the mean CTC loss."""
    right, per_class, loss_sum, seen = 0, {}, 0.0, 0
    with torch.no_grad():
        for width, positions in crops.batches(batch):
            x, _, targets, chosen = crops.batch(width, positions)
            logits = net(x, stop=logits_at)
            loss_sum += tail.ctc_loss(logits, targets).item() * len(chosen)
            seen += len(chosen)
            best = columns[logits[..., columns].argmax(-1)].cpu()
            for k, i in enumerate(chosen):
                ok = tail.read_text(best[k].tolist(), characters) == crops.texts[i]
                right += ok
                per_class.setdefault(crops.classes[i], [0, 0])[0] += ok
    for c in crops.classes:
        per_class.setdefault(c, [0, 0])[1] += 1
    return (right / len(crops), {c: r / n for c, (r, n) in sorted(per_class.items())},
            loss_sum / max(seen, 1))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--base", required=True)
    ap.add_argument("--dict", required=True)
    ap.add_argument("--train", required=True, nargs="+")
    ap.add_argument("--val", required=True, nargs="+")
    ap.add_argument("--out", required=True)
    ap.add_argument("--alphabet", default="0123456789ABCDEFGHIJKLMNOPQRSTUVWXYZ-")
    ap.add_argument("--learn-from", default="",
                    help="first weight that learns (default: the graph's first, i.e. all)")
    ap.add_argument("--device", default="cuda" if torch.cuda.is_available() else "cpu")
    ap.add_argument("--seconds", type=float, default=300, help="training time to plan for")
    ap.add_argument("--max-steps", type=int, default=0, help="stop after this many (0: none)")
    ap.add_argument("--lr", type=float, default=5e-4)
    ap.add_argument("--warmup", type=int, default=100, help="steps of rising learning rate")
    ap.add_argument("--batch", type=int, default=96)
    ap.add_argument("--pull", type=float, default=1e-4,
                    help="weight of the L2 distance to the base tensors in the loss")
    ap.add_argument("--no-augment", action="store_true")
    ap.add_argument("--val-every", type=int, default=300)
    ap.add_argument("--seed", type=int, default=1)
    args = ap.parse_args()

    torch.manual_seed(args.seed)
    rng = random.Random(args.seed)
    g = torch.Generator(device=args.device)
    g.manual_seed(args.seed)
    characters, class_of = tail.load_charset(args.dict)
    columns = tail.alphabet_columns(args.alphabet, class_of).to(args.device)
    net = OnnxGraph(args.base).to_device(args.device)
    logits_at = tail.logits_name(net)
    t0 = time.time()
    train = Crops(load_crops(args.train), class_of, args.device)
    val = Crops(load_crops(args.val), class_of, args.device)
    print(f"train {len(train)} crops ({train.feasible} wide enough), val {len(val)}; "
          f"loaded in {time.time() - t0:.1f} s on {args.device}", flush=True)

    learn_from = args.learn_from or net.parameter_names()[0]
    learned = tail.learned_tensors(net, columns, learn_from)
    stock = {name: p.detach().clone() for name, p in learned.items()}
    print(f"learning {len(learned)} tensors, {sum(p.numel() for p in learned.values())} values",
          flush=True)

    def check(label):
        exact, per_class, loss = evaluate(net, val, logits_at, characters, columns, 48)
        classes = ", ".join(f"class {c} {v:.3f}" for c, v in per_class.items())
        print(f"{label}: val exact {exact:.4f} ({classes}), val loss {loss:.4f}", flush=True)
        return exact, per_class, loss

    before = check("before")
    metadata = {"base": os.path.basename(args.base), "train": args.train, "val": args.val,
                "train_crops": len(train), "val_crops": len(val), "alphabet": args.alphabet,
                "learn_from": learn_from, "lr": args.lr, "pull": args.pull,
                "batch": args.batch, "augment": not args.no_augment, "seed": args.seed,
                "before": {"val_exact_alphabet": before[0], "per_class": before[1]}}
    best, best_step = before, 0
    tail.save(learned, columns, args.out, {**metadata, "step": 0, "after": metadata["before"]})

    def checkpoint(step):
        """Checks val now, and writes the tensors when they beat the best so far."""
        nonlocal best, best_step
        result = check(f"step {step} ({time.time() - started:.0f} s)")
        if result[0] > best[0]:
            best, best_step = result, step
            tail.save(learned, columns, args.out,
                      {**metadata, "step": step,
                       "after": {"val_exact_alphabet": result[0], "per_class": result[1]}})

    opt = torch.optim.AdamW(list(learned.values()), lr=args.lr, weight_decay=0.0)
    total_steps, step, started = args.max_steps or 10**9, 0, time.time()
    while step < total_steps:
        for width, positions in train.batches(args.batch, rng):
            if step >= total_steps:
                break
            if step == 30:  # plan the run from the speed of the first steps
                per_step = (time.time() - started) / 30
                planned = max(int(args.seconds / per_step), step + 1)
                total_steps = min(args.max_steps or planned, planned)
                print(f"{per_step * 1000:.0f} ms a step: {total_steps} steps planned", flush=True)
            warm = min(1.0, (step + 1) / args.warmup)
            fall = 0.5 * (1 + math.cos(math.pi * min(1.0, step / max(total_steps, 1))))
            for group in opt.param_groups:
                group["lr"] = args.lr * warm * (0.02 + 0.98 * fall)
            x, widths, targets, _ = train.batch(width, positions)
            if not args.no_augment:
                x = augment(x, widths, g)
            loss = tail.ctc_loss(net(x, stop=logits_at), targets)
            opt.zero_grad()
            (loss + args.pull * tail.pull_to_stock(learned, stock)).backward()
            opt.step()
            step += 1
            if step % 50 == 0:
                print(f"step {step}: loss {loss.item():.4f}", flush=True)
            if step % args.val_every == 0:
                checkpoint(step)
    if step % args.val_every != 0:
        checkpoint(step)
    print(f"best: step {best_step}, val exact {best[0]:.4f} {best[1]}, written to {args.out}",
          flush=True)


if __name__ == "__main__":
    main()

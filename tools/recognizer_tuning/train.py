"""Fine-tunes the tail of PP-OCRv4's CTC recognizer on crops written by the C++ exporter
(writeRecognizerTrainingData: DIR/index.tsv lines `CROP.png<TAB>TEXT<TAB>CLASS`, 48 px tall
BGR crops; the class column is not used here).

    /usr/bin/python3 tools/recognizer_tuning/train.py \
        --base third_party/models/paddleocr/ch_PP-OCRv4_rec_infer.onnx \
        --dict third_party/models/ppocr_keys_v1.txt \
        --train /work/data/rec_train [MORE...] --val /work/data/rec_val [MORE...] \
        --out models/recognizer_tuning.npz

The graph up to a cut (--features; by default the SVTR neck's output) stays as PaddleOCR
trained it: its output is computed once per crop, and only what comes after it learns. By
default that is the head: the two convolutions with their batch-norm scale and shift (running
statistics frozen); --learn-from NAME with an earlier cut learns every weight from NAME on
(e.g. the backbone's last stage and the neck). Of the classifier only the columns of the CTC
blank and of --alphabet's characters learn; the other classes keep their weights but still
take part in the softmax. An L2 pull toward the stock values keeps it from forgetting. The
epoch with the best val exact match, decoding over blank + alphabet only, is written: convs and
batch norms whole, the classifier's columns as NAME plus NAME#columns (float16 values), which
tools/detector_tuning/apply_tuning.py puts into the ONNX model at set-up.

--keep FOLDER... names crops of ordinary text (generic_crops.py) that hold the model to its
base's reading: per CTC step, cross-entropy over all classes toward the base model's best class
at that step, weighted by --keep-weight. Learning the garage's text moves the neck that every
class reads through; without this the tuned model forgets real text (`parkloc eval photos`).
"""
import argparse
import os
import random
import sys
import time

import numpy as np
import torch
import torch.nn.functional as F

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..",
                                "detector_tuning"))
from onnx_graph import OnnxGraph  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from crop_index import crops_of  # noqa: E402

FEATURES = "p2o.Concat.8"  # [N, 960, 1, T]: the neck's output, input of the head
# The backbone's last stage starts here, [N, 240, 12, W / 4]; its first weight follows.
LAST_STAGE_CUT, LAST_STAGE_FIRST_WEIGHT = "p2o.Add.159", "conv2d_177.w_0"
# The backbone's output, [N, 480, 1, T], where the SVTR neck starts (its convolutions,
# transformer blocks and shortcut concatenation); its first weight follows.
NECK_CUT, NECK_FIRST_WEIGHT = "p2o.AveragePool.1", "conv2d_142.w_0"
HEAD_TENSORS = ["conv2d_145.w_0", "batch_norm2d_151.w_0", "batch_norm2d_151.b_0",
                "conv2d_146.w_0", "batch_norm2d_152.w_0", "batch_norm2d_152.b_0"]
CLASSIFIER = ["linear_85.w_0", "linear_85.b_0"]  # MatMul weight (120, C) and bias (C,)
BLANK = 0
HEIGHT = 48
STEP = 8  # input pixels per CTC time step
# The C++ feeds every crop padded to at least this width (CtcRecognizer::kInputWidth, as
# PaddleOCR does); the committed models/recognizer_tuning.npz was trained so.
INPUT_WIDTH = 320


# ----- data -------------------------------------------------------------------------------

def load_charset(path):
    """Class of each character as the C++ Charset numbers them: 0 blank, line i -> class i,
    then a space; a character listed twice keeps its first class."""
    if not os.path.isfile(path):
        raise SystemExit(f"train.py: dictionary {path} not found")
    with open(path, encoding="utf-8") as f:
        characters = [line.rstrip("\n").rstrip("\r") for line in f]
    characters.append(" ")
    class_of = {}
    for i, ch in enumerate(characters):
        class_of.setdefault(ch, i + 1)
    return characters, class_of


def load_split(folders):
    """[(BGR crop, text)] of every FOLDER/index.tsv, in order."""
    return [sample for folder in folders for sample in load_folder(folder)]


def load_folder(folder):
    """[(BGR crop, text)] of FOLDER/index.tsv."""
    samples = []
    for rel, image, fields in crops_of(folder, "train.py"):
        if image.shape[0] != HEIGHT:
            raise SystemExit(f"train.py: {rel} in {folder} is no {HEIGHT} px tall image")
        samples.append((image, fields[1]))
    if not samples:
        raise SystemExit(f"train.py: no crops in {folder}/index.tsv")
    return samples


def encode(text, class_of):
    missing = [ch for ch in text if ch not in class_of]
    if missing:
        raise SystemExit(f"train.py: text {text!r} has characters not in the dictionary: "
                         f"{''.join(missing)!r}")
    return [class_of[ch] for ch in text]


def normalise(bgr, width):
    """As the C++ packs a crop: BGR order, (v/255 - 0.5)/0.5, zeros on the right to `width`."""
    x = np.zeros((3, HEIGHT, width), np.float32)
    x[:, :, : bgr.shape[1]] = (bgr.astype(np.float32) / 255.0 - 0.5).transpose(2, 0, 1) / 0.5
    return x


def padded_width(width, extra=0):
    return max(INPUT_WIDTH, (width + extra + STEP - 1) // STEP * STEP)


# ----- features: the frozen stock graph up to the cut, once per crop ----------------------

def extract_features(net, images, widths, batch, cut):
    """float16 output of the graph up to `cut` for each image (without the batch axis), input
    padded to its entry of `widths`; images of equal width are run together."""
    features = [None] * len(images)
    by_width = {}
    for i, w in enumerate(widths):
        by_width.setdefault(w, []).append(i)
    with torch.no_grad():
        for w, indices in sorted(by_width.items()):
            for k in range(0, len(indices), batch):
                chunk = indices[k: k + batch]
                x = torch.from_numpy(np.stack([normalise(images[i], w) for i in chunk]))
                y = net(x, stop=cut).to(torch.float16)
                for i, f in zip(chunk, y):
                    features[i] = f.clone()
    return features


class Split:
    """Features, targets and texts of one split, with batches of equal time steps."""

    def __init__(self, net, samples, class_of, extra_pad, rng, batch, cut):
        self.texts = [text for _, text in samples]
        self.targets = [encode(text, class_of) for text in self.texts]
        widths = [padded_width(img.shape[1], rng.randint(0, extra_pad // STEP) * STEP)
                  for img, _ in samples]
        t0 = time.time()
        self.features = extract_features(net, [img for img, _ in samples], widths, batch, cut)
        self.extract_ms = 1000 * (time.time() - t0) / len(samples)
        steps = [w // STEP for w in widths]
        # CTC needs a step per label plus a blank between repeated labels.
        self.feasible = [i for i, t in enumerate(self.targets) if ctc_min_steps(t) <= steps[i]]
        self.by_steps = {}
        for i in self.feasible:
            self.by_steps.setdefault(steps[i], []).append(i)

    def __len__(self):
        return len(self.features)

    def batches(self, size, rng=None):
        """Lists of sample indices with equal T; shuffled when rng is given."""
        out = []
        for indices in self.by_steps.values():
            indices = list(indices)
            if rng:
                rng.shuffle(indices)
            out += [indices[k: k + size] for k in range(0, len(indices), size)]
        if rng:
            rng.shuffle(out)
        return out

    def inputs(self, indices):
        x = torch.stack([self.features[i] for i in indices]).float()
        return x, [self.targets[i] for i in indices]


def base_steps(net, split, cut, logits_at, batch):
    """For each crop of `split`, the base model's best class at each CTC step (int64 [T]),
    before any weight learns: what --keep holds the model to."""
    best = [None] * len(split)
    with torch.no_grad():
        for indices in split.batches(batch):
            x, _ = split.inputs(indices)
            for i, b in zip(indices, net(x, start=cut, stop=logits_at).argmax(-1)):
                best[i] = b.clone()
    return best


def keep_batches(keep, size, rng):
    """Endless shuffled batches of the --keep crops (equal T within a batch)."""
    while True:
        for indices in keep.batches(size, rng):
            yield indices


def keep_loss(net, keep, targets, indices, cut, logits_at):
    x, _ = keep.inputs(indices)
    logits = net(x, start=cut, stop=logits_at)
    y = torch.stack([targets[i] for i in indices])
    return F.cross_entropy(logits.reshape(-1, logits.shape[-1]), y.reshape(-1))


def keep_agreement(net, keep, targets, cut, logits_at, characters, batch):
    """Share of --keep crops read exactly as the base model reads them."""
    same = 0
    with torch.no_grad():
        for indices in keep.batches(batch):
            x, _ = keep.inputs(indices)
            best = net(x, start=cut, stop=logits_at).argmax(-1)
            for k, i in enumerate(indices):
                same += (read_text(best[k].tolist(), characters) ==
                         read_text(targets[i].tolist(), characters))
    return same / max(len(keep), 1)


def ctc_min_steps(target):
    return len(target) + sum(a == b for a, b in zip(target, target[1:]))


# ----- the head ---------------------------------------------------------------------------

def logits_name(net):
    """The Softmax's input at the graph's end: the classifier's logits [N, T, C]."""
    softmax = net.nodes[net.producer[net.output_name]]
    assert softmax.op_type == "Softmax", softmax.op_type
    return softmax.input[0]


def ctc_loss(logits, targets):
    """Mean over the batch of each crop's CTC loss."""
    log_probs = F.log_softmax(logits, dim=-1).transpose(0, 1)  # [T, N, C]
    n, steps = logits.shape[0], logits.shape[1]
    device = logits.device
    flat = torch.tensor([c for t in targets for c in t], dtype=torch.int64, device=device)
    lengths = torch.tensor([len(t) for t in targets], dtype=torch.int64, device=device)
    steps_all = torch.full((n,), steps, dtype=torch.int64, device=device)
    losses = F.ctc_loss(log_probs, flat, steps_all, lengths,
                        blank=BLANK, reduction="none", zero_infinity=True)
    return losses.mean()


def greedy_decode(classes):
    """CTC best path: repeats merged, blanks dropped."""
    out, previous = [], BLANK
    for c in classes:
        if c != previous and c != BLANK:
            out.append(c)
        previous = c
    return out


def read_text(classes, characters):
    return "".join(characters[c - 1] for c in greedy_decode(classes))


def evaluate(net, split, cut, logits_at, characters, columns, batch):
    """Val exact match decoding over all classes and over `columns` only, and mean CTC loss
    (crops too narrow for their text count as misread, and are left out of the loss)."""
    right_all = right_cols = 0
    loss_sum = 0.0
    with torch.no_grad():
        for indices in split.batches(batch):
            x, targets = split.inputs(indices)
            logits = net(x, start=cut, stop=logits_at)
            loss_sum += ctc_loss(logits, targets).item() * len(indices)
            best_all = logits.argmax(-1)
            best_cols = columns[logits[..., columns].argmax(-1)]
            for k, i in enumerate(indices):
                right_all += read_text(best_all[k].tolist(), characters) == split.texts[i]
                right_cols += read_text(best_cols[k].tolist(), characters) == split.texts[i]
    n = len(split)
    return right_all / n, right_cols / n, loss_sum / max(len(split.feasible), 1)


# ----- training ---------------------------------------------------------------------------

def learned_tensors(net, columns, learn_from):
    """{ONNX name: trainable tensor}: the head's, or every weight from `learn_from` on; the
    classifier narrowed to `columns`."""
    ordered = net.parameter_names()
    names = set(ordered)
    whole = HEAD_TENSORS
    if learn_from:
        if learn_from not in names:
            raise SystemExit(f"train.py: --learn-from {learn_from} is not a weight of the model")
        whole = [n for n in ordered[ordered.index(learn_from):] if n not in CLASSIFIER]
    for name in whole + CLASSIFIER:
        if name not in names:
            raise SystemExit(f"train.py: {name} is not a trainable weight of the base model")
    for name in names:
        net.weight(name).requires_grad_(False)
    learned = {}
    for name in whole:
        learned[name] = net.weight(name).requires_grad_(True)
    for name in CLASSIFIER:
        learned[name] = net.learn_only_columns(name, columns)
    return learned


def pull_to_stock(learned, stock):
    return sum(((p - stock[name]) ** 2).sum() for name, p in learned.items())


def train_epoch(net, split, logits_at, learned, stock, opt, args, rng, keep=None):
    """keep: (split, base targets, batch generator) of the --keep crops, or None."""
    total, batches = 0.0, split.batches(args.batch, rng)
    for indices in batches:
        x, targets = split.inputs(indices)
        loss = ctc_loss(net(x, start=args.features, stop=logits_at), targets)
        objective = loss + args.pull * pull_to_stock(learned, stock)
        if keep:
            keep_split, keep_targets, keep_gen = keep
            objective = objective + args.keep_weight * keep_loss(
                net, keep_split, keep_targets, next(keep_gen), args.features, logits_at)
        opt.zero_grad()
        objective.backward()
        opt.step()
        total += loss.item()
    return total / max(len(batches), 1)


def save(learned, columns, path, metadata):
    tensors = {}
    for name, p in learned.items():
        tensors[name] = p.detach().cpu().numpy().astype(np.float16)
        if name in CLASSIFIER:
            tensors[name + "#columns"] = columns.cpu().numpy().astype(np.int64)
    tmp = path + ".tmp.npz"
    np.savez_compressed(tmp, **tensors, __metadata__=np.array(repr(metadata)))
    os.replace(tmp, path)


def alphabet_columns(alphabet, class_of):
    chars = list(dict.fromkeys(alphabet))
    missing = [ch for ch in chars if ch not in class_of]
    if missing:
        raise SystemExit(f"train.py: --alphabet characters not in the dictionary: {missing}")
    return torch.tensor([BLANK] + [class_of[ch] for ch in chars], dtype=torch.int64)


def report(label, accuracy_all, accuracy_cols, loss):
    print(f"{label}: val exact match {accuracy_all:.3f} (all classes), "
          f"{accuracy_cols:.3f} (blank + alphabet), val loss {loss:.4f}", flush=True)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--base", required=True)
    ap.add_argument("--dict", required=True)
    ap.add_argument("--train", required=True, nargs="+", help="crop folders, one or more")
    ap.add_argument("--val", required=True, nargs="+", help="crop folders, one or more")
    ap.add_argument("--out", required=True)
    ap.add_argument("--alphabet", default="0123456789ABCDEFGHIJKLMNOPQRSTUVWXYZ-")
    ap.add_argument("--features", default=FEATURES,
                    help="graph output computed once per crop, where learning starts; "
                         f"{NECK_CUT} is the backbone's output, {LAST_STAGE_CUT} the input "
                         "of its last stage")
    ap.add_argument("--learn-from", default="",
                    help="first weight that learns, every later one learning too (default: "
                         f"the head only); {NECK_FIRST_WEIGHT} follows {NECK_CUT}, "
                         f"{LAST_STAGE_FIRST_WEIGHT} {LAST_STAGE_CUT}")
    ap.add_argument("--epochs", type=int, default=8)
    ap.add_argument("--lr", type=float, default=5e-4)
    ap.add_argument("--batch", type=int, default=32)
    ap.add_argument("--pull", type=float, default=1e-3,
                    help="weight of the L2 distance to the stock tensors in the loss")
    ap.add_argument("--extra-pad", type=int, default=16,
                    help="train crops get 0..this many px of extra right padding (beyond "
                         "INPUT_WIDTH only), as the C++ batches of similar width give them")
    ap.add_argument("--keep", nargs="*", default=[],
                    help="crop folders of ordinary text the model keeps reading as its base does")
    ap.add_argument("--keep-weight", type=float, default=1.0)
    ap.add_argument("--extract-batch", type=int, default=32)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--threads", type=int, default=1,
                    help="torch threads; on a loaded 2-core machine 2 threads make every small "
                         "operator wait for the other core (several times slower)")
    args = ap.parse_args()

    torch.manual_seed(args.seed)
    torch.set_num_threads(args.threads)
    rng = random.Random(args.seed)
    characters, class_of = load_charset(args.dict)
    columns = alphabet_columns(args.alphabet, class_of)
    net = OnnxGraph(args.base)
    logits_at = logits_name(net)

    train = Split(net, load_split(args.train), class_of, args.extra_pad, rng, args.extract_batch,
                  args.features)
    val = Split(net, load_split(args.val), class_of, 0, rng, args.extract_batch, args.features)
    for label, split in (("train", train), ("val", val)):
        print(f"{label}: {len(split)} crops, {len(split) - len(split.feasible)} too narrow for "
              f"their text, features {split.extract_ms:.1f} ms/crop", flush=True)
        outside = sum(any(ch not in args.alphabet for ch in t) for t in split.texts)
        if outside:
            print(f"{label}: {outside} texts have characters outside --alphabet", flush=True)

    keep = None
    if args.keep:
        keep_split = Split(net, load_split(args.keep), class_of, 0, rng, args.extract_batch,
                           args.features)
        keep_targets = base_steps(net, keep_split, args.features, logits_at, args.batch)
        keep = (keep_split, keep_targets, keep_batches(keep_split, args.batch, rng))
        print(f"keep: {len(keep_split)} crops of ordinary text, the base's reading the target",
              flush=True)

    learned = learned_tensors(net, columns, args.learn_from)
    stock = {name: p.detach().clone() for name, p in learned.items()}
    print(f"learning {len(learned)} tensors, {sum(p.numel() for p in learned.values())} values "
          f"({len(columns)} classifier columns)", flush=True)
    before = evaluate(net, val, args.features, logits_at, characters, columns, args.batch)
    report("before", *before)
    metadata = {"base": os.path.basename(args.base), "train": args.train, "val": args.val,
                "train_crops": len(train), "val_crops": len(val), "alphabet": args.alphabet,
                "features": args.features, "learn_from": args.learn_from, "lr": args.lr, "pull": args.pull, "batch": args.batch,
                "keep": args.keep, "keep_weight": args.keep_weight,
                "before": {"val_exact_all": before[0], "val_exact_alphabet": before[1],
                           "val_loss": before[2]}}
    best, best_epoch = before, 0
    save(learned, columns, args.out, {**metadata, "epoch": 0, "after": metadata["before"]})

    opt = torch.optim.Adam(list(learned.values()), lr=args.lr)
    for epoch in range(1, args.epochs + 1):
        t0 = time.time()
        train_loss = train_epoch(net, train, logits_at, learned, stock, opt, args, rng, keep)
        seconds = time.time() - t0
        result = evaluate(net, val, args.features, logits_at, characters, columns, args.batch)
        report(f"epoch {epoch} (train loss {train_loss:.4f}, {seconds:.1f} s)", *result)
        if keep:
            agreement = keep_agreement(net, keep[0], keep[1], args.features, logits_at,
                                       characters, args.batch)
            print(f"epoch {epoch}: --keep crops read as the base reads them: {agreement:.3f}",
                  flush=True)
        if result[1] > best[1]:
            best, best_epoch = result, epoch
            save(learned, columns, args.out,
                 {**metadata, "epoch": epoch,
                  "after": {"val_exact_all": result[0], "val_exact_alphabet": result[1],
                            "val_loss": result[2]}})
    report(f"after (best epoch {best_epoch}, written to {args.out})", *best)


if __name__ == "__main__":
    main()

"""Fine-tunes PP-OCRv4's DB detector on floor views written by `parkloc train detector-data`.

    python3 tools/detector_tuning/train.py --base third_party/models/paddleocr/ch_PP-OCRv4_det_infer.onnx \
        --train DATA_TRAIN --val DATA_VAL --out models/detector_ground_tuning.npz

Only the layers from --train-from on (by default the FPN neck and the DB head) learn; the
backbone keeps PaddleOCR's weights, so what the network knows of scene text stays, and the
file written holds only the tensors that changed. apply_tuning.py puts them into the ONNX model
at set-up. Loss as DB trains its probability map: balanced BCE (hard negatives 3:1) + dice.

--keep DIR (images of ordinary text, generic_scenes.py) with --keep-base MODEL (PaddleOCR's
detector) adds, at every step, the BCE between the map learned and the base model's map on
random crops of those images, weighted by --keep-weight: the fine-tuned detector keeps finding
the text PaddleOCR's finds outside a garage (`parkloc eval photos`).
"""
import argparse
import os
import random
import sys
import time

import cv2
import numpy as np
import torch

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from db_targets import probability_targets  # noqa: E402
from onnx_graph import OnnxGraph  # noqa: E402

MEAN = np.array([0.485, 0.456, 0.406], np.float32)  # as src/ocr/ppocr/pp_ocr_networks.cc
STD = np.array([0.229, 0.224, 0.225], np.float32)


def load_split(folder, limit=0, in_memory=True):
    """[(image, care quads, don't-care quads)]; with in_memory False the image is its path,
    read when used (a few thousand views would take a dozen gigabytes)."""
    samples = []
    with open(os.path.join(folder, "index.txt")) as f:
        lines = [l.split() for l in f if l.strip()]
    if limit:
        lines = lines[:limit]
    for image_rel, label_rel, *_ in lines:
        path = os.path.join(folder, image_rel)
        image = read_view(path) if in_memory else path
        care, dont = [], []
        with open(os.path.join(folder, label_rel)) as f:
            for line in f:
                parts = line.rstrip("\n").split(",")
                if len(parts) < 10:
                    continue
                quad = np.array(parts[:8], np.float32).reshape(4, 2)
                (care if parts[8] == "1" else dont).append(quad)
        samples.append((image, care, dont))
    return samples


def read_view(path):
    image = cv2.imread(path, cv2.IMREAD_COLOR)
    if image is None:
        raise SystemExit(f"train.py: cannot read {path}")
    return image


def normalise(bgr):
    x = (bgr.astype(np.float32) / 255.0 - MEAN) / STD
    return x.transpose(2, 0, 1)


def augment(image, care, dont, crop, rng, scales=(0.8, 1.25)):
    h, w = image.shape[:2]
    scale = rng.uniform(*scales)
    m = np.array([[scale, 0, 0], [0, scale, 0]], np.float32)
    # Centre the crop on a text instance most of the time, so that batches hold text.
    if care and rng.random() < 0.8:
        c = care[rng.randrange(len(care))].mean(axis=0) * scale
        cx = c[0] + rng.uniform(-0.35, 0.35) * crop
        cy = c[1] + rng.uniform(-0.35, 0.35) * crop
    else:
        cx, cy = rng.uniform(0, w * scale), rng.uniform(0, h * scale)
    m[0, 2] = crop / 2 - cx
    m[1, 2] = crop / 2 - cy
    if rng.random() < 0.5:  # turned by 180 degrees: the other reading direction
        m = np.array([[-1, 0, crop - 1], [0, -1, crop - 1]], np.float32) @ np.vstack([m, [0, 0, 1]])
        m = m.astype(np.float32)
    out = cv2.warpAffine(image, m, (crop, crop), flags=cv2.INTER_LINEAR,
                         borderMode=cv2.BORDER_CONSTANT, borderValue=(0, 0, 0))

    def move(quads):
        return [np.hstack([q, np.ones((4, 1), np.float32)]) @ m.T for q in quads]

    care, dont = move(care), move(dont)
    # Photometric changes: weak light, glare, blur, sensor noise.
    f = out.astype(np.float32)
    f = f * rng.uniform(0.5, 1.4) + rng.uniform(-25, 25)
    if rng.random() < 0.3:
        f = 255.0 * np.power(np.clip(f, 0, 255) / 255.0, rng.uniform(0.7, 1.5))
    if rng.random() < 0.3:
        f = cv2.GaussianBlur(f, (0, 0), rng.uniform(0.5, 1.8))
    if rng.random() < 0.5:
        f = f + np.random.default_rng(rng.randrange(1 << 30)).normal(0, rng.uniform(2, 8), f.shape)
    out = np.clip(f, 0, 255).astype(np.uint8)
    return out, care, dont


def binary_cross_entropy(p, target, eps=1e-6):
    """Per pixel, of the map `p` against `target` (0..1), p kept off 0 and 1."""
    p = p.clamp(eps, 1 - eps)
    return -(target * torch.log(p) + (1 - target) * torch.log(1 - p))


def db_loss(p, target, weight):
    eps = 1e-6
    bce = binary_cross_entropy(p, target, eps)
    p = p.clamp(eps, 1 - eps)
    pos = (target > 0.5) & (weight > 0)
    neg = (target < 0.5) & (weight > 0)
    n_pos = int(pos.sum())
    n_neg = min(int(neg.sum()), max(3 * n_pos, 1000))
    neg_loss, _ = torch.topk(bce[neg], n_neg)
    balanced = (bce[pos].sum() + neg_loss.sum()) / (n_pos + n_neg + eps)
    inter = (p * target * weight).sum()
    dice = 1 - 2 * inter / ((p * weight).sum() + (target * weight).sum() + eps)
    return balanced + dice


def instance_recall(net, samples, threshold=0.3):
    """Share of care instances whose shrunk core the map covers (mean prob > threshold), and
    share of map pixels above the threshold outside every instance: a quick proxy of recall
    and of false alarms; `parkloc eval ocr` gives the real figures."""
    found = total = 0
    false_px = all_px = 0
    with torch.no_grad():
        for image, care, dont in samples:
            p = net(torch.from_numpy(normalise(image))[None])[0, 0].numpy()
            for q in care:
                t, _ = probability_targets(p.shape, [q], [])
                if t.sum() < 1:
                    continue
                total += 1
                found += p[t > 0].mean() > threshold
            outside = np.ones(p.shape, np.uint8)
            for q in care + dont:
                cv2.fillPoly(outside, [np.round(q).astype(np.int32)], 0)
            false_px += int(((p > threshold) & (outside > 0)).sum())
            all_px += int(outside.sum())
    return found / max(total, 1), total, false_px / max(all_px, 1)


def keep_crop(image, crop, rng):
    """A random crop of a --keep image at a random scale, as the detector meets text of any
    size."""
    scale = rng.uniform(0.5, 1.5)
    h, w = image.shape[:2]
    m = np.array([[scale, 0, 0], [0, scale, 0]], np.float32)
    m[0, 2] = -rng.uniform(0, max(0.0, w * scale - crop))
    m[1, 2] = -rng.uniform(0, max(0.0, h * scale - crop))
    return cv2.warpAffine(image, m, (crop, crop), flags=cv2.INTER_LINEAR,
                          borderMode=cv2.BORDER_REPLICATE)


def keep_agreement(net, base, images, threshold=0.3):
    """Of the pixels the base model's map puts above the threshold on the --keep check
    images, the share the learned map also does: how much of ordinary text it still finds."""
    both = base_on = 0
    with torch.no_grad():
        for image in images:
            x = torch.from_numpy(normalise(image))[None]
            on = base(x)[0, 0] > threshold
            both += int((on & (net(x)[0, 0] > threshold)).sum())
            base_on += int(on.sum())
    return both / max(base_on, 1)


def save(net, names, path, metadata):
    tensors = {n: net.weight(n).detach().numpy().astype(np.float16) for n in names}
    tmp = path + ".tmp.npz"
    np.savez_compressed(tmp, **tensors, __metadata__=np.array(repr(metadata)))
    os.replace(tmp, path)


def checkpoint_path(out, step):
    return f"{os.path.splitext(out)[0]}.step{step}.npz"


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--base", required=True)
    ap.add_argument("--train", required=True)
    ap.add_argument("--val", required=True)
    ap.add_argument("--out", required=True)
    ap.add_argument("--train-from", default="conv2d_131.w_0",
                    help="first ONNX weight that learns (default: the neck's first conv)")
    ap.add_argument("--minutes", type=float, default=40)
    ap.add_argument("--crop", type=int, default=320)
    ap.add_argument("--batch", type=int, default=8)
    ap.add_argument("--lr", type=float, default=5e-4)
    ap.add_argument("--val-every", type=int, default=100)
    ap.add_argument("--val-images", type=int, default=60)
    ap.add_argument("--scale", type=float, nargs=2, default=[0.8, 1.25], metavar=("MIN", "MAX"),
                    help="range of the views' random scale (below 1: text smaller than the "
                         "floor view draws it, as a photo's may be)")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--keep", default="",
                    help="folder of images of ordinary text (index.txt) whose map the model "
                         "keeps as --keep-base draws it")
    ap.add_argument("--keep-base", default="", help="the model whose map --keep holds to")
    ap.add_argument("--keep-weight", type=float, default=1.0)
    ap.add_argument("--keep-checkpoints", action="store_true",
                    help="also write OUT's stem + .stepN.npz at every check and at the end, to "
                         "choose by `parkloc eval ocr` rather than by the quick check")
    args = ap.parse_args()

    torch.manual_seed(args.seed)
    torch.set_num_threads(args.threads)
    rng = random.Random(args.seed)
    net = OnnxGraph(args.base)
    names = net.parameter_names()
    if args.train_from not in names:
        raise SystemExit(f"train.py: --train-from {args.train_from} is not a weight of the model")
    first = names.index(args.train_from)
    learn = names[first:]
    for n in names:
        net.weight(n).requires_grad_(n in learn)
    params = [net.weight(n) for n in learn]
    print(f"learning {len(learn)} tensors, {sum(p.numel() for p in params)} values", flush=True)

    train = load_split(args.train, in_memory=False)
    val = load_split(args.val)
    val = val[:: max(1, len(val) // args.val_images)][: args.val_images]
    print(f"{len(train)} train views, {len(val)} val views", flush=True)
    keep_images, keep_check, keep_base = [], [], None
    if args.keep:
        if not args.keep_base:
            raise SystemExit("train.py: --keep needs --keep-base")
        keep_base = OnnxGraph(args.keep_base)
        for n in keep_base.parameter_names():
            keep_base.weight(n).requires_grad_(False)
        with open(os.path.join(args.keep, "index.txt")) as f:
            keep_images = [read_view(os.path.join(args.keep, l.strip())) for l in f if l.strip()]
        keep_check = keep_images[-20:]  # the check's images, never trained on
        keep_images = keep_images[:-20]
        print(f"keep: {len(keep_images)} images of ordinary text, {len(keep_check)} to check; "
              f"base agreement {keep_agreement(net, keep_base, keep_check):.3f}", flush=True)
    r, n, fp = instance_recall(net, val)
    print(f"before: val core recall {r:.3f} of {n}, false pixels {fp:.4f}", flush=True)
    best = (r - 10 * fp, 0)
    save(net, learn, args.out, {"step": 0, "val_recall": r, "val_false_px": fp})

    opt = torch.optim.AdamW(params, lr=args.lr, weight_decay=1e-4)
    start = time.time()
    budget = args.minutes * 60
    step = 0
    while time.time() - start < budget:
        batch, targets, weights = [], [], []
        for _ in range(args.batch):
            path, care, dont = train[rng.randrange(len(train))]
            img, c, d = augment(read_view(path), care, dont, args.crop, rng, args.scale)
            t, w = probability_targets((args.crop, args.crop), c, d)
            batch.append(normalise(img))
            targets.append(t)
            weights.append(w)
        x = torch.from_numpy(np.stack(batch))
        t = torch.from_numpy(np.stack(targets))[:, None]
        w = torch.from_numpy(np.stack(weights))[:, None]
        lr = args.lr * 0.5 * (1 + np.cos(np.pi * min(1.0, (time.time() - start) / budget)))
        for g in opt.param_groups:
            g["lr"] = lr
        loss = db_loss(net(x), t, w)
        if keep_images:
            k = torch.from_numpy(np.stack([
                normalise(keep_crop(keep_images[rng.randrange(len(keep_images))], args.crop, rng))
                for _ in range(max(1, args.batch // 2))]))
            with torch.no_grad():
                target = keep_base(k)
            keep_term = binary_cross_entropy(net(k), target).mean()
            loss = loss + args.keep_weight * keep_term
        opt.zero_grad()
        loss.backward()
        opt.step()
        step += 1
        if step % 10 == 0:
            print(f"step {step} loss {loss.item():.4f} lr {lr:.2e} "
                  f"{(time.time() - start) / step:.2f} s/step", flush=True)
        if step % args.val_every == 0:
            r, n, fp = instance_recall(net, val)
            print(f"step {step}: val core recall {r:.3f} of {n}, false pixels {fp:.4f}", flush=True)
            if keep_base is not None:
                print(f"step {step}: base agreement on ordinary text "
                      f"{keep_agreement(net, keep_base, keep_check):.3f}", flush=True)
            if args.keep_checkpoints:
                save(net, learn, checkpoint_path(args.out, step),
                     {"step": step, "val_recall": r, "val_false_px": fp})
            if r - 10 * fp > best[0]:
                best = (r - 10 * fp, step)
                save(net, learn, args.out, {"step": step, "val_recall": r, "val_false_px": fp})
                print(f"saved {args.out}", flush=True)
    r, n, fp = instance_recall(net, val)
    print(f"final step {step}: val core recall {r:.3f} of {n}, false pixels {fp:.4f}", flush=True)
    if args.keep_checkpoints:
        save(net, learn, checkpoint_path(args.out, step),
             {"step": step, "val_recall": r, "val_false_px": fp})
    if r - 10 * fp > best[0]:
        save(net, learn, args.out, {"step": step, "val_recall": r, "val_false_px": fp})
        best = (r - 10 * fp, step)
    print(f"best at step {best[1]} -> {args.out}", flush=True)


if __name__ == "__main__":
    main()

"""Random changes to a batch of recognizer inputs, on whatever device the batch is on, so that
a recognizer trained on a few thousand rendered crops sees paint and light it was not shown:
faded and worn paint, dim and noisy images, blur, and the small misfits of a detected box.

    x = augment(x, widths, generator)

x is a batch as the recognizer takes it: [N, 3, 48, W] float, BGR scaled to -1..1, each crop
at the left and zeros (grey) to its right; widths[i] is the width of crop i. Nothing here
knows how the simulator draws text: every change is a generic image change (contrast, blotches
toward the local background, blur, noise, an affine jitter) with ranges wide enough to cover
real garages too.
"""
import math

import torch
import torch.nn.functional as F


def _uniform(n, low, high, g, device):
    return low + (high - low) * torch.rand(n, generator=g, device=device)


def _chance(n, p, g, device):
    return torch.rand(n, generator=g, device=device) < p


def content_mask(widths, shape, device):
    """[N, 1, H, W] 1 where a crop has pixels, 0 in its right padding."""
    columns = torch.arange(shape[3], device=device)[None, :]
    inside = (columns < torch.as_tensor(widths, device=device)[:, None]).float()
    return inside[:, None, None, :].expand(shape[0], 1, shape[2], shape[3])


def _smooth_field(n, h, w, cells_y, cells_x, g, device):
    """[N, 1, h, w] smooth noise in 0..1: random values on a coarse grid, upsampled."""
    coarse = torch.rand(n, 1, cells_y, cells_x, generator=g, device=device)
    return F.interpolate(coarse, size=(h, w), mode="bicubic", align_corners=False).clamp(0, 1)


def _box_blur(x, size):
    return F.avg_pool2d(x, size, stride=1, padding=size // 2, count_include_pad=False)


def _gaussian_blur(x, sigma):
    """Each image blurred by its own sigma (pixels), separably; sigma 0 leaves it."""
    radius = 4
    offsets = torch.arange(-radius, radius + 1, device=x.device, dtype=x.dtype)
    s = sigma.clamp(min=1e-3)[:, None]
    kernel = torch.exp(-0.5 * (offsets[None, :] / s) ** 2)
    kernel = kernel / kernel.sum(1, keepdim=True)  # [N, K]
    n, c, h, w = x.shape
    flat = x.reshape(1, n * c, h, w)
    k = kernel.repeat_interleave(c, 0)
    flat = F.conv2d(flat, k[:, None, None, :], padding=(0, radius), groups=n * c)
    flat = F.conv2d(flat, k[:, None, :, None], padding=(radius, 0), groups=n * c)
    return flat.reshape(n, c, h, w)


def _affine(x, widths, g):
    """A small rotation, shear, scale and shift of each crop about its own centre."""
    n, _, h, w = x.shape
    device = x.device
    angle = _uniform(n, -4, 4, g, device) * math.pi / 180
    shear = _uniform(n, -0.25, 0.25, g, device)
    scale_x = _uniform(n, 0.85, 1.15, g, device)
    scale_y = _uniform(n, 0.85, 1.12, g, device)
    shift_x = _uniform(n, -4, 4, g, device)
    shift_y = _uniform(n, -3, 3, g, device)
    cos, sin = torch.cos(angle), torch.sin(angle)
    # Output pixel -> input pixel, about the crop's centre: A = R * Shear * Scale^-1.
    a00 = cos / scale_x
    a01 = (cos * shear - sin) / scale_y
    a10 = sin / scale_x
    a11 = (sin * shear + cos) / scale_y
    # In grid_sample's normalised coordinates (u = 2 p / size - 1): M = S A S^-1.
    m00, m01, m10, m11 = a00, a01 * h / w, a10 * w / h, a11
    cx = torch.as_tensor(widths, device=device, dtype=x.dtype) / w - 1  # centre, normalised
    cy = torch.zeros(n, device=device, dtype=x.dtype)
    tx = cx - (m00 * cx + m01 * cy) + 2 * shift_x / w
    ty = cy - (m10 * cx + m11 * cy) + 2 * shift_y / h
    theta = torch.stack([torch.stack([m00, m01, tx], 1), torch.stack([m10, m11, ty], 1)], 1)
    grid = F.affine_grid(theta, list(x.shape), align_corners=False)
    return F.grid_sample(x, grid, mode="bilinear", padding_mode="border", align_corners=False)


def augment(x, widths, g, p_clean=0.15):
    """The batch with each crop changed at random (a share p_clean of them left as they are);
    the right padding stays grey (0)."""
    n, c, h, w = x.shape
    device = x.device
    inside = content_mask(widths, x.shape, device)
    out = x.clone()

    # Worn paint: blotches where the image falls back toward its local background.
    wear = _chance(n, 0.4, g, device)
    if wear.any():
        background = _box_blur(out, 15)
        field = _smooth_field(n, h, w, 4, max(4, w // 12), g, device)
        level = _uniform(n, 0.45, 0.85, g, device)[:, None, None, None]
        strength = _uniform(n, 0.5, 1.0, g, device)[:, None, None, None]
        blotch = ((field > level).float() * strength) * wear[:, None, None, None].float()
        speckle = (torch.rand(n, 1, h, w, generator=g, device=device) <
                   _uniform(n, 0.0, 0.2, g, device)[:, None, None, None]).float()
        blotch = torch.maximum(blotch, speckle * wear[:, None, None, None].float() * 0.7)
        out = out + blotch * (background - out)

    # Contrast and brightness: faded ink, dim or bright light, a slight colour cast.
    mean = (out * inside).sum((2, 3), keepdim=True) / inside.sum((2, 3), keepdim=True).clamp(1)
    contrast = _uniform(n, 0.35, 1.15, g, device)[:, None, None, None]
    brightness = _uniform(n, -0.35, 0.3, g, device)[:, None, None, None]
    cast = _uniform(n * c, -0.06, 0.06, g, device).reshape(n, c, 1, 1)
    out = mean + contrast * (out - mean) + brightness + cast

    blur = _chance(n, 0.4, g, device)
    if blur.any():
        sigma = _uniform(n, 0.4, 1.8, g, device) * blur.float()
        out = torch.where(blur[:, None, None, None], _gaussian_blur(out, sigma), out)

    noise = _uniform(n, 0.0, 0.1, g, device)[:, None, None, None]
    out = out + noise * torch.randn(out.shape, generator=g, device=device)

    moved = _chance(n, 0.6, g, device)
    if moved.any():
        out = torch.where(moved[:, None, None, None], _affine(out, widths, g), out)

    out = out.clamp(-1, 1) * inside
    clean = _chance(n, p_clean, g, device)[:, None, None, None]
    return torch.where(clean, x, out)

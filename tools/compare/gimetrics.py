"""Image errors as docs/metrics.md defines them, and the time at which an error curve reaches a target."""
import math

import numpy as np


def read_linear_rgb(path):
    """A linear HDR/EXR image as a float64 array of shape (height, width, 3).

    Reads through ImageInput rather than ImageBuf, which goes through OpenImageIO's image cache: reading renders that
    rewrote one file name through ImageBuf sometimes returned the previous renderer's pixels."""
    import OpenImageIO as oiio  # imported here so the unit tests need only numpy

    inp = oiio.ImageInput.open(str(path))
    if inp is None:
        raise RuntimeError(f"cannot read {path}: {oiio.geterror()}")
    try:
        pixels = inp.read_image(oiio.FLOAT)
        spec = inp.spec()
    finally:
        inp.close()
    if pixels is None or spec.nchannels < 3:
        raise RuntimeError(f"{path}: expected an RGB image ({inp.geterror() if pixels is None else spec.nchannels})")
    pixels = pixels.reshape(spec.height, spec.width, spec.nchannels)
    return pixels[:, :, :3].astype(np.float64)


def luminance(rgb):
    return 0.2126 * rgb[..., 0] + 0.7152 * rgb[..., 1] + 0.0722 * rgb[..., 2]


def image_error(image, reference):
    """rRMSE, bad-pixel fraction and the count of non-finite pixels of `image` against `reference`.

    Pixels that are NaN or infinite in either image are counted and left out of the two figures; any of them is a
    failure whatever the figures say (docs/metrics.md)."""
    if image.shape != reference.shape:
        raise ValueError(f"image {image.shape} and reference {reference.shape} differ in size")
    finite = np.isfinite(image).all(axis=2) & np.isfinite(reference).all(axis=2)
    non_finite = int((~finite).sum())
    img, ref = image[finite], reference[finite]  # (n, 3)
    mean_ref = ref.mean() if ref.size else 0.0
    rrmse = math.sqrt(((img - ref) ** 2).mean()) / mean_ref if mean_ref > 0 else math.inf
    y_img, y_ref = luminance(img), luminance(ref)
    bad = np.abs(y_img - y_ref) > 0.1 * y_ref + 0.01 * (y_ref.mean() if y_ref.size else 0.0)
    return {"rrmse": float(rrmse), "bad_fraction": float(bad.mean()) if bad.size else 1.0, "non_finite": non_finite}


def crossing_time(points, target):
    """When an error-against-time curve first reaches `target`.

    `points` are (seconds, error) pairs, one per quality setting. They are sorted by time and joined by straight
    lines in log-log space; the answer is the first time the curve is at or below `target`, or None when no point
    is. Returns (seconds, exact): exact is False when even the fastest point already meets the target, so the
    true crossing lies at or before the returned time."""
    pts = sorted((t, e) for t, e in points if t > 0 and e is not None and not math.isnan(e))
    if not pts:
        return None, False
    if pts[0][1] <= target:
        return pts[0][0], False
    tiny = 1e-12
    for (t0, e0), (t1, e1) in zip(pts, pts[1:]):
        if e1 <= target:
            # Linear in (log t, log e) between the last point above the target and the first one at or below it.
            le0, le1, lt = math.log(max(e0, tiny)), math.log(max(e1, tiny)), math.log(target)
            f = (le0 - lt) / (le0 - le1) if le0 != le1 else 1.0
            return math.exp(math.log(t0) + f * (math.log(t1) - math.log(t0))), True
    return None, False

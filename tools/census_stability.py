"""The census's instability test: does POV-Ray's own picture of a deterministic scene hang on rounding?

A scene whose pixels sit exactly on an edge (an orthographic camera whose pixel centres fall on line edges), or
whose texture is chaotic at the scale of a pixel (turbulence 20 with 30 octaves), is pictured by POV-Ray one way
and, after a change far below a pixel, another: at one sample a pixel a comparison of two renderers then measures
rounding, not rendering. The census turns every camera of the scene's folder by a tiny angle
(CAMERA_TURN, degrees about each axis; about 2e-6 radians, 2e-4 of a pixel at 120x90, moving the camera by about
2e-6 of its distance from the origin) and renders POV-Ray again; a scene whose POV-Ray image moves by more than
the match tolerance is unstable at one sample a pixel and is judged on supersampled renders (SUPERSAMPLED_AA) of
both programs instead, each with the cameras turned (so that no sample sits exactly on a tie, where each
program's last bits decide), with POV-Ray's own supersampled movement under the turn as its noise floor.
"""
import re

from povrewrite import RewriteError, find_blocks, mask_comments_and_strings

# Degrees about x, y and z: unequal, so that no axis of the picture keeps its ties.
CAMERA_TURN = (1.0e-4, 1.3e-4, 0.7e-4)
# Every pixel supersampled 4x4 without jitter, in both programs alike: an even grid, so that no sample sits on the
# pixel centre, where the ties of an unstable scene lie (at 3x3 the centre sample counted them again: Twindragon).
SUPERSAMPLED_AA = ("+A0.0", "+R4", "-J")
MARKER = "/* perturbed by tools/census.py */"


def turn_text():
    x, y, z = CAMERA_TURN
    return f" rotate <{x:.7f}, {y:.7f}, {z:.7f}> {MARKER} "


def perturb_cameras(text):
    """(the text with `rotate CAMERA_TURN` appended inside every `camera { ... }` block, the number of blocks).

    A block that names a declared camera (`camera { Cam }`) takes the turn too: POV-Ray applies transformations
    after a camera identifier. A declared camera used later is turned twice, which is as tiny. Raises RewriteError
    when the braces do not pair up."""
    masked = mask_comments_and_strings(text)
    blocks = find_blocks(masked, "camera")
    out, last = [], 0
    for _, close_at in blocks:
        out += [text[last:close_at], turn_text()]
        last = close_at
    out.append(text[last:])
    return "".join(out), len(blocks)


def perturbed_texts(files):
    """{name: text with its cameras turned (perturb_cameras)} for the scene's files `[(name, text)]` that lie
    directly in its folder and hold a camera block. Raises RewriteError saying why the cameras cannot be turned: no
    camera block in the folder's files (the camera is in an include file from elsewhere, or the scene uses the
    default camera), a camera in a file of a subfolder (linked to the original, never written through), or braces
    that do not pair up."""
    done, elsewhere = {}, []
    for name, text in files:
        try:
            new, n = perturb_cameras(text)
        except RewriteError as e:
            raise RewriteError(f"{name}: {e}") from e
        if n and "/" in name:
            elsewhere.append(name)
        elif n:
            done[name] = new
    if elsewhere:
        raise RewriteError(f"a camera in {elsewhere[0]}, a subfolder's file the census does not rewrite")
    if not done:
        raise RewriteError("no camera block in the scene's folder (the default camera, or one from an include "
                           "file elsewhere)")
    return done


def perturbed_copy(files, work):
    """Writes perturbed_texts(files) into the scratch folder `work`; the names written."""
    texts = perturbed_texts(files)
    for name, text in texts.items():
        (work / name).unlink(missing_ok=True)  # never write through a link into the original
        (work / name).write_text(text)
    return sorted(texts)


def supersampled_options(cmd):
    """A render command with `-A` replaced by SUPERSAMPLED_AA."""
    return [x for a in cmd for x in (SUPERSAMPLED_AA if a == "-A" else (a,))]


def moved(metrics, match_rrmse, match_bad):
    """Whether POV-Ray's image moved beyond the match tolerance when its camera turned (metrics of the turned image
    against the original)."""
    return (metrics["non_finite"] == 0 and metrics["non_finite_wardray"] == 0
            and (metrics["rrmse"] > match_rrmse or metrics["bad"] > match_bad))


def supersampled_tolerance(floor, match_rrmse, match_bad):
    """(rRMSE, bad-pixel fraction) within which wardray's supersampled image matches POV-Ray's: the match
    tolerance, or POV-Ray's own supersampled movement under the camera turn (`floor`, its metrics) where that is
    larger: a renderer that differs from POV-Ray no more than POV-Ray differs from itself cannot be told apart."""
    if not floor:
        return match_rrmse, match_bad
    return max(match_rrmse, floor["rrmse"]), max(match_bad, floor["bad"])


def turn_label():
    x, y, z = CAMERA_TURN
    return f"camera turned by <{x:g}, {y:g}, {z:g}>°"


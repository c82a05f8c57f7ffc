"""Rewrites the `radiosity { }` block(s) inside a POV-Ray scene's `global_settings` with given settings.

The comparison tool renders one scene at many quality settings; it writes a wrapper scene per setting whose text
is the original with every radiosity block of `global_settings` overridden. POV-Ray reads a radiosity block's
settings in order and the last one wins, so the overrides are appended just before the block's closing brace;
that also overrides settings that come from macros or `#switch` branches. Where an overridden keyword is followed
by a plain number, the old setting is removed too so the wrapper reads cleanly. Comments and strings are skipped;
POV-Ray's block comments nest.
"""
import re

# Keywords a `radiosity` block takes a single numeric value for (POV-Ray 3.7 reference, 3.4.8.2).
NUMERIC_KEYS = ("adc_bailout", "always_sample", "brightness", "count", "error_bound", "gray_threshold",
                "low_error_factor", "max_sample", "maximum_reuse", "minimum_reuse", "nearest_count",
                "pretrace_end", "pretrace_start", "recursion_limit")

_NUMBER = r"[+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?"


class RewriteError(ValueError):
    """The scene text cannot be rewritten (unbalanced braces or comments)."""


def mask_comments_and_strings(text):
    """Returns `text` with every comment and string literal replaced by spaces (newlines kept), same length."""
    out = list(text)
    i, n = 0, len(text)

    def blank(a, b):
        for k in range(a, b):
            if out[k] != "\n":
                out[k] = " "

    while i < n:
        c = text[i]
        if text.startswith("//", i):
            end = text.find("\n", i)
            end = n if end < 0 else end
            blank(i, end)
            i = end
        elif text.startswith("/*", i):
            # POV-Ray compat: block comments nest.
            depth, j = 1, i + 2
            while j < n and depth:
                if text.startswith("/*", j):
                    depth, j = depth + 1, j + 2
                elif text.startswith("*/", j):
                    depth, j = depth - 1, j + 2
                else:
                    j += 1
            if depth:
                raise RewriteError(f"unterminated block comment starting at offset {i}")
            blank(i, j)
            i = j
        elif c == '"':
            j = i + 1
            while j < n and text[j] != '"' and text[j] != "\n":
                j += 2 if text[j] == "\\" else 1
            if j >= n or text[j] != '"':
                raise RewriteError(f"unterminated string starting at offset {i}")
            blank(i + 1, j)  # keep the quotes so tokens stay apart
            i = j + 1
        else:
            i += 1
    return "".join(out)


def matching_brace(masked, open_at):
    """Index of the `}` that closes the `{` at `open_at` in comment-free text."""
    depth = 0
    for j in range(open_at, len(masked)):
        if masked[j] == "{":
            depth += 1
        elif masked[j] == "}":
            depth -= 1
            if depth == 0:
                return j
    raise RewriteError(f"unbalanced '{{' at offset {open_at}")


def find_blocks(masked, keyword, start=0, end=None):
    """(open, close) brace offsets of every `keyword { ... }` in masked[start:end], outermost only."""
    end = len(masked) if end is None else end
    pattern = re.compile(r"(?<![A-Za-z0-9_])" + re.escape(keyword) + r"\s*\{")
    blocks, pos = [], start
    while True:
        m = pattern.search(masked, pos, end)
        if not m:
            return blocks
        open_at = m.end() - 1
        close_at = matching_brace(masked, open_at)
        if close_at >= end:
            raise RewriteError(f"'{keyword}' block at offset {m.start()} runs past its enclosing block")
        blocks.append((open_at, close_at))
        pos = close_at + 1


def format_settings(settings, indent="    "):
    """Radiosity settings as POV-Ray text, one per line, in the given order."""
    lines = []
    for key, value in settings.items():
        if isinstance(value, bool):
            value = "on" if value else "off"
        elif isinstance(value, (list, tuple)):
            value = ", ".join(str(v) for v in value)
        lines.append(f"{indent}{key} {value}")
    return "\n".join(lines)


def _strip_simple(body, masked_body, keys):
    """Removes `key NUMBER[, NUMBER]` for each key in `keys` when nothing but a keyword, directive or brace follows."""
    spans = []
    for key in keys:
        pattern = re.compile(r"(?<![A-Za-z0-9_#])" + re.escape(key) + r"\s+" + _NUMBER + r"(?:\s*,\s*" + _NUMBER + ")?")
        for m in pattern.finditer(masked_body):
            rest = masked_body[m.end():].lstrip()
            if rest == "" or rest[0].isalpha() or rest[0] in "#}_":
                spans.append((m.start(), m.end()))
    for a, b in sorted(spans, reverse=True):
        body = body[:a] + body[b:]
        masked_body = masked_body[:a] + masked_body[b:]
    return body


def rewrite_radiosity(text, settings, marker="set by tools/compare"):
    """The scene text with `settings` (ordered dict keyword -> value) overriding every radiosity block in
    global_settings; adds a radiosity block (and global_settings) when the scene has none.

    Returns (new_text, how) where how is "replaced", "injected" or "appended"."""
    masked = mask_comments_and_strings(text)
    overrides = format_settings(settings)
    globals_ = find_blocks(masked, "global_settings")
    radiosity = [b for g_open, g_close in globals_ for b in find_blocks(masked, "radiosity", g_open + 1, g_close)]
    if radiosity:
        # Work from the end so earlier offsets stay valid.
        for open_at, close_at in sorted(radiosity, reverse=True):
            body = _strip_simple(text[open_at + 1:close_at], masked[open_at + 1:close_at], settings.keys())
            body = body.rstrip() + f"\n    // {marker}\n{overrides}\n  "
            text = text[:open_at + 1] + body + text[close_at:]
        return text, "replaced"
    block = f"\n  radiosity {{  // {marker}\n{overrides}\n  }}\n"
    if globals_:
        open_at = globals_[0][0]
        return text[:open_at + 1] + block + text[open_at + 1:], "injected"
    return text.rstrip("\n") + f"\n\nglobal_settings {{{block}}}\n", "appended"

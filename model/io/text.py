"""The layout of every command's text: the answer first, then the details, then what the
tool assumed (issue 26).

:func:`layout` is the one arrangement every result view's ``summary()`` uses:

1. the **answer** (the loss, the optimum, the front, the grade, the p95; at most a few
   lines, so it is within the first 5 lines of stdout);
2. the **body** (tables, notes), as the view writes it;
3. the **assumptions** (the case, the thermal mode and why, gamma and its source, the
   block of defaults the tool filled in): after the answer, left out with
   ``defaults=False`` (``oilgap ... -q``).

Prose lines longer than :data:`WIDTH` are wrapped (:func:`wrap`) with a hanging indent
under their label; table rows are left as they are.
"""

from __future__ import annotations

import re
import textwrap
from collections.abc import Iterable, Sequence

WIDTH = 100
"""Width of the text commands print [characters]."""

_GLUE = re.compile(r"(?<=\d) (?=(?:%|W|K|J|s|ms|mm|m|degC|cSt|Wh|h|rpm|N m|kg|x)(?![\w/^]))")
"""The space between a number and its unit: never a line break ("34.9 W", "-29 %")."""
_NBSP = "\u00a0"

_LABEL = re.compile(r"^(\s*)(\S(?:[^ ]| (?! ))*?\s{2,}|\S[^:]{0,30}: )")
"""A line's label: ``thermal     `` (a word padded to its column) or ``film band: ``."""


def wrap(line: str, width: int = WIDTH) -> list[str]:
    """One prose line as lines of at most ``width`` characters (a word longer than the
    width stays whole, a number stays with its unit), continuation lines indented under
    the text after the label.

    Parameters
    ----------
    line : str
        The line [-].
    width : int
        The width [characters].

    Returns
    -------
    list of str
        ``[line]`` when it fits.
    """
    if len(line) <= width:
        return [line]
    m = _LABEL.match(line)
    indent = len(m.group(0)) if m and len(m.group(0)) <= 40 else \
        len(line) - len(line.lstrip()) + 2
    out = textwrap.wrap(_GLUE.sub(_NBSP, line), width, subsequent_indent=" " * indent,
                        break_long_words=False, break_on_hyphens=False)
    return [x.replace(_NBSP, " ") for x in out] or [line]


def wrapped(lines: Iterable[str], width: int = WIDTH) -> list[str]:
    """Each of ``lines`` through :func:`wrap`.

    Parameters
    ----------
    lines : iterable of str
        Prose lines [-].
    width : int
        The width [characters].

    Returns
    -------
    list of str
        The lines, each wrapped in place [-].
    """
    return [x for line in lines for x in wrap(line, width)]


def layout(answer: Sequence[str], body: Sequence[str] = (), assumptions: Sequence[str] = (),
           tail: Sequence[str] = (), defaults: bool = True) -> str:
    """A command's text: answer, body, assumptions (only with ``defaults``), tail (the
    ``wrote`` lines), separated by blank lines; answer and assumptions wrapped.

    Parameters
    ----------
    answer : sequence of str
        The result in a few lines (first on stdout) [-].
    body : sequence of str
        Tables and notes, as given (blank lines kept inside) [-].
    assumptions : sequence of str
        The case, thermal mode, gamma, the defaults filled in [-].
    tail : sequence of str
        Lines that close the text (the files written) [-].
    defaults : bool
        Print the assumptions (False: ``-q``) [-].

    Returns
    -------
    str
        The text, lines of at most :data:`WIDTH` characters but the body's tables [-].
    """
    blocks = [wrapped(answer), _trim(body), wrapped(assumptions) if defaults else [],
              _trim(tail)]
    out: list[str] = []
    for b in blocks:
        if b:
            out += ([""] if out else []) + list(b)
    return "\n".join(out)


def _trim(lines: Sequence[str]) -> list[str]:
    """``lines`` without leading and trailing blank lines."""
    lines = list(lines)
    while lines and not lines[0].strip():
        lines.pop(0)
    while lines and not lines[-1].strip():
        lines.pop()
    return lines


__all__ = ["WIDTH", "layout", "wrap", "wrapped"]

"""Reader for the namelist text LANDYN stores in /meta/resolved_input.

The resolved input is written by LANDYN itself (``landyn --check`` prints the same text), so
this reader only supports the subset of namelist syntax that writer uses:

* groups ``&name`` ... ``/``, ``!`` comments, one assignment per line;
* ``name = v1, v2, ...`` with repeat counts ``3*0.0``;
* subscripts ``name(:, 2)``, ``name(1:4)``, ``name(3)``, ``name(1:2, 5)`` (1-based, Fortran order);
* values: reals and integers (``1.0e-6``, ``1.0d-6``), ``.true.``/``.false.`` and quoted strings
  (``'it''s'``).

The parsed deck maps ``group -> variable -> {index tuple: value}``; :meth:`Namelist.get` returns
scalars and :meth:`Namelist.array` dense arrays. Names are case-insensitive.
"""
from __future__ import annotations

import re

import numpy as np

__all__ = ["Namelist", "NamelistError", "parse_namelist"]


class NamelistError(ValueError):
    """The text is not a namelist deck of the supported form."""


_ASSIGN = re.compile(r"^\s*([A-Za-z_][A-Za-z0-9_]*)\s*(\(([^)]*)\))?\s*=\s*(.*)$")


def _strip_comment(line: str) -> str:
    """Removes a trailing ``!`` comment that is not inside a quoted string."""
    quote = None
    for i, ch in enumerate(line):
        if quote:
            if ch == quote:
                quote = None
        elif ch in "'\"":
            quote = ch
        elif ch == "!":
            return line[:i]
    return line


def _split_values(text: str) -> list[str]:
    """Splits a value list at commas outside quotes."""
    items, cur, quote = [], [], None
    for ch in text:
        if quote:
            cur.append(ch)
            if ch == quote:
                quote = None
        elif ch in "'\"":
            quote = ch
            cur.append(ch)
        elif ch == ",":
            items.append("".join(cur).strip())
            cur = []
        else:
            cur.append(ch)
    last = "".join(cur).strip()
    if last or items:
        items.append(last)
    return [x for x in items if x != ""]


def _value(token: str):
    """Converts one namelist value to int, float, bool or str."""
    t = token.strip()
    if len(t) >= 2 and t[0] == t[-1] and t[0] in "'\"":
        q = t[0]
        return t[1:-1].replace(q + q, q)
    low = t.lower()
    if low in (".true.", ".t.", "t"):
        return True
    if low in (".false.", ".f.", "f"):
        return False
    try:
        return int(t)
    except ValueError:
        pass
    try:
        return float(low.replace("d", "e"))
    except ValueError as exc:
        raise NamelistError(f"cannot read value {token!r}") from exc


def _expand(values_text: str) -> list:
    out = []
    for item in _split_values(values_text):
        m = re.match(r"^(\d+)\*(.+)$", item)
        if m and not item.startswith(("'", '"')):
            out.extend([_value(m.group(2))] * int(m.group(1)))
        else:
            out.append(_value(item))
    return out


def _indices(subscript: str | None, n_values: int) -> list[tuple[int, ...]]:
    """Index tuples (1-based) that an assignment with this subscript fills, in Fortran order."""
    if subscript is None:
        return [(i + 1,) for i in range(n_values)] if n_values > 1 else [()]
    dims = []
    for part in subscript.split(","):
        part = part.strip()
        if part == ":":
            dims.append(None)
        elif ":" in part:
            lo, hi = part.split(":")
            dims.append(list(range(int(lo), int(hi) + 1)))
        else:
            dims.append([int(part)])
    free = [k for k, d in enumerate(dims) if d is None]
    if len(free) > 1:
        raise NamelistError(f"subscript ({subscript}) has more than one ':'")
    if free:
        dims[free[0]] = list(range(1, n_values // max(1, _prod(d for d in dims if d is not None)) + 1))
    # Fortran order: first index fastest.
    idx = [()]
    for d in dims:
        idx = [i + (v,) for v in d for i in idx]
    idx.sort(key=lambda t: t[::-1])
    return idx


def _prod(lists) -> int:
    n = 1
    for d in lists:
        n *= len(d)
    return n


class Namelist:
    """A parsed deck: ``groups[group][name][index] = value`` (index a 1-based tuple, () for scalars)."""

    def __init__(self, groups: dict[str, dict[str, dict[tuple, object]]]):
        self.groups = groups

    def has(self, group: str, name: str) -> bool:
        return name.lower() in self.groups.get(group.lower(), {})

    def _var(self, group: str, name: str) -> dict[tuple, object]:
        try:
            return self.groups[group.lower()][name.lower()]
        except KeyError:
            raise NamelistError(f"the resolved input has no &{group} {name}") from None

    def get(self, group: str, name: str):
        """A scalar value (the first element of an array)."""
        var = self._var(group, name)
        if () in var:
            return var[()]
        return var[min(var)]

    def array(self, group: str, name: str, shape: tuple[int, ...], fill=np.nan) -> np.ndarray:
        """A dense array of the given Fortran shape (1-based indices), missing entries = fill.

        Returned in Fortran index order: ``a[i-1, j-1]`` is ``name(i, j)``.
        """
        var = self._var(group, name)
        out = np.full(shape, fill, dtype=float)
        for idx, val in var.items():
            if idx == ():
                idx = (1,) * len(shape)
            if len(idx) != len(shape):
                if len(shape) == 1 and len(idx) == 2:
                    raise NamelistError(f"&{group} {name} has two subscripts, expected one")
                raise NamelistError(f"&{group} {name}: subscript {idx} does not fit shape {shape}")
            if all(1 <= i <= s for i, s in zip(idx, shape)):
                out[tuple(i - 1 for i in idx)] = float(val)
        return out


def parse_namelist(text: str) -> Namelist:
    """Parses namelist text (see the module documentation)."""
    groups: dict[str, dict[str, dict[tuple, object]]] = {}
    current: dict | None = None
    for lineno, raw in enumerate(text.splitlines(), 1):
        line = _strip_comment(raw).strip()
        if not line:
            continue
        if line.startswith("&"):
            name = line[1:].split()[0].lower() if len(line) > 1 else ""
            if not name:
                raise NamelistError(f"line {lineno}: '&' without a group name")
            current = groups.setdefault(name, {})
            rest = line[1 + len(name):].strip()
            if rest in ("", "/"):
                if rest == "/":
                    current = None
                continue
            line = rest
        if line == "/":
            current = None
            continue
        if current is None:
            raise NamelistError(f"line {lineno}: assignment outside a group: {raw.strip()!r}")
        end_group = False
        if line.endswith("/") and not line.endswith("'/") and line.count("'") % 2 == 0:
            line, end_group = line[:-1].strip(), True
        m = _ASSIGN.match(line)
        if not m:
            raise NamelistError(f"line {lineno}: not an assignment: {raw.strip()!r}")
        name, subscript, values_text = m.group(1).lower(), m.group(3), m.group(4)
        values = _expand(values_text)
        idx = _indices(subscript, len(values))
        if len(idx) != len(values):
            raise NamelistError(f"line {lineno}: {len(values)} values for {len(idx)} elements of {name}")
        var = current.setdefault(name, {})
        for i, v in zip(idx, values):
            var[i] = v
        if end_group:
            current = None
    return Namelist(groups)

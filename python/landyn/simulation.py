"""The Simulation class: one LANDYN touchdown simulation (a handle of the C API, include/landyn.h)."""
from __future__ import annotations

import ctypes
import os
import threading
from pathlib import Path
from typing import Dict, Iterable, Mapping, Optional, Sequence, Tuple, Union

import numpy as np

from . import _lib
from .errors import LandynClosedError, LandynInputError, LandynOutputNameError, error_for

DeckLike = Union[str, "os.PathLike[str]", None]
OverridesLike = Union[str, Mapping[str, object], None]

#: Outcome codes of the output ``outcome`` (LANDYN_OUTCOME_* of include/landyn.h) and their names.
OUTCOMES: Dict[int, str] = {0: "running", 1: "no_touchdown", 2: "at_rest", 3: "still_moving", 4: "tipped_over",
                            5: "failed"}

_MSG_LEN = 4096          # messages of advance, outputs, files [characters]
_CREATE_MSG_LEN = 65536  # every problem of a deck [characters]


def version() -> str:
    """The library's version, git revision and compiler (one line), as landyn_version returns it."""
    return _lib.load().landyn_version().decode("utf-8", "replace")


def _value_text(value: object) -> str:
    """A Python value as namelist text: numbers exactly (repr), strings quoted, logicals, sequences."""
    if isinstance(value, (bool, np.bool_)):
        return ".true." if value else ".false."
    if isinstance(value, str):
        return "'" + value.replace("'", "''") + "'"
    if isinstance(value, (int, np.integer)):
        return str(int(value))
    if isinstance(value, (float, np.floating)):
        return repr(float(value))
    if isinstance(value, (Sequence, np.ndarray)):
        return ", ".join(_value_text(v) for v in value)
    raise LandynInputError(f"overrides: value {value!r} of type {type(value).__name__} is not a number, "
                           f"string, logical or sequence of them")


def overrides_text(overrides: OverridesLike) -> str:
    """Deck text for ``overrides``: text as it is, or a mapping ``{"group%variable": value}``.

    ``{"initial_state%velocity(3)": 5.0, "simulation%t_end": 0.5}`` gives
    ``&initial_state velocity(3) = 5.0 /`` and ``&simulation t_end = 0.5 /`` (one line per group).
    """
    if overrides is None:
        return ""
    if isinstance(overrides, str):
        return overrides
    if not isinstance(overrides, Mapping):
        raise LandynInputError(f"overrides: deck text or a mapping {{'group%variable': value}} expected, "
                               f"got {type(overrides).__name__}")
    groups: Dict[str, list] = {}
    for key, value in overrides.items():
        group, sep, var = str(key).partition("%")
        if not sep or not group.strip() or not var.strip():
            raise LandynInputError(f"overrides: key {key!r} is not 'group%variable' "
                                   f"(e.g. 'initial_state%velocity(3)')")
        groups.setdefault(group.strip(), []).append(f"{var.strip()} = {_value_text(value)}")
    return "".join(f"&{g} {', '.join(items)} /\n" for g, items in groups.items())


def _deck_text(deck: DeckLike) -> Tuple[str, Optional[str]]:
    """(deck text, the file it came from or None) for deck text, a path to a deck file, or None."""
    if deck is None:
        return "", None
    if isinstance(deck, os.PathLike) or (isinstance(deck, str) and "\n" not in deck and "&" not in deck
                                         and deck.strip()):
        path = Path(os.fspath(deck))
        try:
            return path.read_text(encoding="utf-8"), str(path)
        except (OSError, UnicodeDecodeError) as exc:
            raise LandynInputError(f"deck file {str(path)!r} cannot be read: {exc} (a str with neither '&' "
                                   f"nor a newline is taken as the path of a deck file)") from exc
    if isinstance(deck, str):
        return deck, None
    raise LandynInputError(f"deck: deck text, a path or None expected, got {type(deck).__name__}")


class Simulation:
    """One touchdown simulation of the C API: create from a deck, advance, read outputs, write the result.

    ``Simulation(deck=None, *, overrides=None)``: ``deck`` is deck text (a namelist as a deck file holds
    it), a path (``str`` without ``&`` or a newline, or ``os.PathLike``) to a deck file, or None for the
    defaults (the paper's lander in load case LC-1); ``overrides`` is deck text applied on top of it, or
    a mapping ``{"group%variable": value}`` (``{"initial_state%velocity(3)": 5.0}``). Every input check
    of the ``landyn`` program applies; a bad deck raises :class:`LandynInputError` whose message lists
    every problem (group, variable, value). The simulation starts at t = 0 s.

    Units are SI (m, s, N, N m, kg) unless :attr:`units` says otherwise (angles of outputs in deg).
    Use it as a context manager, or call :meth:`close`; after closing every method raises
    :class:`LandynClosedError`. A Simulation may be used from several threads (calls are serialised);
    two Simulations are independent.
    """

    def __init__(self, deck: DeckLike = None, *, overrides: OverridesLike = None) -> None:
        self._handle: Optional[ctypes.c_void_p] = None   # None until created: a half-built object frees nothing
        self._lock = threading.RLock()
        self._lib = _lib.load()
        text, self.deck_file = _deck_text(deck)
        extra = overrides_text(overrides)
        self._msg = ctypes.create_string_buffer(_MSG_LEN)
        msg = ctypes.create_string_buffer(_CREATE_MSG_LEN)
        handle = ctypes.c_void_p()
        name = (self.deck_file or "").encode("utf-8")   # the file names the deck in messages and provenance
        status = self._lib.landyn_create_named(text.encode("utf-8"), name, extra.encode("utf-8"),
                                               ctypes.byref(handle), msg, _CREATE_MSG_LEN)
        if status != _lib.OK:
            raise error_for(status, _decode(msg))
        self._handle = handle
        try:
            self._names, self._units, self._meanings = self._read_output_info()
        except BaseException:
            self.close()
            raise
        self._index = {n: i for i, n in enumerate(self._names)}

    # ---- life cycle ---------------------------------------------------------------------------------
    def close(self) -> None:
        """Frees the simulation (idempotent). Every later call raises LandynClosedError."""
        with self._lock:
            if self._handle is not None:
                handle, self._handle = self._handle, None
                self._lib.landyn_free(ctypes.byref(handle))

    @property
    def closed(self) -> bool:
        """True after :meth:`close`."""
        return self._handle is None

    def __enter__(self) -> "Simulation":
        self._live()
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()

    def __del__(self) -> None:
        try:
            self.close()
        except Exception:  # interpreter shutdown: the library may be gone already
            pass

    def __copy__(self) -> "Simulation":
        raise TypeError("a landyn.Simulation cannot be copied (two objects would free one handle); "
                        "create another Simulation from the same deck")

    def __deepcopy__(self, memo: dict) -> "Simulation":
        return self.__copy__()

    def __reduce__(self) -> tuple:
        raise TypeError("a landyn.Simulation cannot be pickled: its state lives in liblandyn.so")

    def __repr__(self) -> str:
        src = f"deck_file={self.deck_file!r}" if getattr(self, "deck_file", None) else "deck=<text>"
        if self._handle is None:
            return f"<landyn.Simulation {src} closed>"
        return (f"<landyn.Simulation {src} t={self.time:.6g} s outcome={self.outcome} "
                f"outputs={len(self._names)}>")

    # ---- calls into the library ---------------------------------------------------------------------
    def _live(self) -> ctypes.c_void_p:
        if self._handle is None:
            raise LandynClosedError("this Simulation was closed; create a new one", 2)
        return self._handle

    def _check(self, status: int) -> int:
        if status != _lib.OK and status != _lib.ENDED:
            raise error_for(status, _decode(self._msg))
        return status

    def _read_output_info(self) -> Tuple[Tuple[str, ...], Dict[str, str], Dict[str, str]]:
        count = ctypes.c_int()
        with self._lock:
            self._check_plain(self._lib.landyn_output_count(self._live(), ctypes.byref(count)), "landyn_output_count")
            name, unit, meaning = (ctypes.create_string_buffer(256), ctypes.create_string_buffer(64),
                                   ctypes.create_string_buffer(1024))
            names, units, meanings = [], {}, {}
            for i in range(count.value):
                self._check_plain(self._lib.landyn_output_info(self._handle, i, name, 256, unit, 64, meaning, 1024),
                                  f"landyn_output_info({i})")
                n = _decode(name)
                names.append(n)
                units[n], meanings[n] = _decode(unit), _decode(meaning)
        return tuple(names), units, meanings

    @staticmethod
    def _check_plain(status: int, what: str) -> None:
        if status != _lib.OK:
            raise error_for(status, f"{what} returned status {status}")

    # ---- time and inputs ----------------------------------------------------------------------------
    @property
    def time(self) -> float:
        """The simulation's time [s]."""
        t = ctypes.c_double()
        with self._lock:
            self._check_plain(self._lib.landyn_time(self._live(), ctypes.byref(t)), "landyn_time")
        return t.value

    def advance_to(self, t: float) -> bool:
        """Advances to time ``t`` [s] (time now <= t <= &simulation t_end; 'fixed' integrator: a whole
        number of steps dt). True when it got to ``t`` (at t_end the run ends there too: see :attr:`ended`);
        False when the run ended before ``t`` (at rest, tipped over: the state stays at the end time,
        see :attr:`outcome`).

        Raises LandynOrderError (t before the simulation's time, past t_end, after a failure),
        LandynInputError (t not finite), LandynFailedError (the simulation diverged).
        """
        t = float(t)
        with self._lock:
            status = self._check(self._lib.landyn_advance_to(self._live(), t, self._msg, _MSG_LEN))
        return status == _lib.OK

    def set_input(self, force: Iterable[float] = (0.0, 0.0, 0.0), moment: Iterable[float] = (0.0, 0.0, 0.0)) -> None:
        """Engine inputs in the lander frame, held from now until the next call: ``force`` [N] at the
        &engine point and a pure ``moment`` [N m] (3 components each; an omitted one is zero). They add
        to the deck's &engine thrust. Raises LandynInputError (not 3 finite numbers), LandynOrderError
        (the run has ended).
        """
        f, m = _vector3(force, "force"), _vector3(moment, "moment")
        p = ctypes.POINTER(ctypes.c_double)
        with self._lock:
            self._check(self._lib.landyn_set_input(self._live(), f.ctypes.data_as(p), m.ctypes.data_as(p),
                                                   self._msg, _MSG_LEN))

    # ---- outputs ------------------------------------------------------------------------------------
    @property
    def output_names(self) -> Tuple[str, ...]:
        """The output names, in the order of :meth:`outputs` (they depend on the deck's gears and struts)."""
        self._live()
        return self._names

    @property
    def units(self) -> Dict[str, str]:
        """Unit of every output, ``{name: unit}`` (e.g. ``"m"``, ``"deg"``, ``"-"``)."""
        self._live()
        return dict(self._units)

    @property
    def meanings(self) -> Dict[str, str]:
        """One-line meaning of every output, ``{name: text}``."""
        self._live()
        return dict(self._meanings)

    def outputs(self) -> np.ndarray:
        """Every output at the current time, a float64 array in the order of :attr:`output_names`."""
        values = np.empty(len(self._names), dtype=np.float64)
        with self._lock:
            self._check(self._lib.landyn_get_outputs(self._live(), values.ctypes.data_as(
                ctypes.POINTER(ctypes.c_double)), values.size, self._msg, _MSG_LEN))
        return values

    def output(self, name: str) -> float:
        """One output at the current time, in its unit (:attr:`units`). Raises LandynOutputNameError
        (a KeyError) for a name the simulation does not have, suggesting the closest."""
        value = ctypes.c_double()
        with self._lock:
            status = self._lib.landyn_get_output(self._live(), str(name).encode("utf-8"), ctypes.byref(value),
                                                 self._msg, _MSG_LEN)
            if status == _lib.ERR_INPUT:
                raise LandynOutputNameError(_decode(self._msg) or f"unknown output {name!r}", status)
            self._check(status)
        return value.value

    __getitem__ = output

    def __contains__(self, name: object) -> bool:
        return name in self._index

    __iter__ = None  # not iterable (sim["name"] is a lookup): iterate over output_names

    def as_dict(self) -> Dict[str, float]:
        """Every output at the current time, ``{name: value}``."""
        return dict(zip(self._names, self.outputs().tolist()))

    @property
    def outcome_code(self) -> int:
        """The output ``outcome``: 0 running, 1 no_touchdown, 2 at_rest, 3 still_moving, 4 tipped_over, 5 failed."""
        return int(self.output("outcome"))

    @property
    def outcome(self) -> str:
        """The outcome as text: ``running`` until the run ended, then ``no_touchdown``, ``at_rest``,
        ``tipped_over``, ``still_moving`` (at t_end, inconclusive) or ``failed``."""
        code = self.outcome_code
        return OUTCOMES.get(code, f"unknown({code})")

    @property
    def ended(self) -> bool:
        """True once the run has ended (its outcome is no longer ``running``)."""
        return self.outcome_code != 0

    def history(self, times: Iterable[float]) -> Dict[str, np.ndarray]:
        """Advances through ``times`` [s] (non-decreasing, from the current time on) and returns every
        output at each of them, ``{name: array}`` in the order of :attr:`output_names`.

        When the run ends before a time (at rest, tipped over), the row of that time holds the end
        state (its ``time`` output is the end time) and the later times are left out: the arrays
        then have fewer rows than ``times``. Raises what :meth:`advance_to` raises.
        """
        ts = np.asarray(list(times) if not isinstance(times, np.ndarray) else times, dtype=np.float64).ravel()
        rows = np.empty((ts.size, len(self._names)), dtype=np.float64)
        n = 0
        for t in ts:
            running = self.advance_to(t)
            rows[n] = self.outputs()
            n += 1
            if not running:
                break
        return {name: rows[:n, i].copy() for i, name in enumerate(self._names)}

    # ---- result file --------------------------------------------------------------------------------
    def write_result(self, path: Union[str, "os.PathLike[str]"]) -> Path:
        """Writes the HDF5 result file (docs/output.md) of what was run so far, with its provenance,
        under the landyn program's output-file policy (docs/files.md: an input file is never
        overwritten, the file is published whole). Returns the path. Raises LandynFileError."""
        p = os.fspath(path)
        with self._lock:
            self._check(self._lib.landyn_write_result(self._live(), os.fsencode(p), self._msg, _MSG_LEN))
        return Path(p)


def _decode(buf: ctypes.Array) -> str:
    return buf.value.decode("utf-8", "replace").strip()


def _vector3(v: Iterable[float], what: str) -> np.ndarray:
    try:
        a = np.array(list(v) if not isinstance(v, np.ndarray) else v, dtype=np.float64).ravel()
    except (TypeError, ValueError) as exc:
        raise LandynInputError(f"set_input: {what} = {v!r} is not 3 numbers [{'N' if what == 'force' else 'N m'}]",
                               1) from exc
    if a.size != 3:
        raise LandynInputError(f"set_input: {what} has {a.size} components, 3 expected "
                               f"(lander frame x, y, z)", 1)
    return np.ascontiguousarray(a)


__all__ = ["Simulation", "OUTCOMES", "version", "overrides_text"]

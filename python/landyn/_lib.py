"""Finding and loading liblandyn.so, and the ctypes prototypes of the C API (include/landyn.h)."""
from __future__ import annotations

import ctypes
import ctypes.util
import functools
import os
from pathlib import Path
from typing import List, Optional

from .errors import LandynLibraryError

LIBRARY_NAME = "liblandyn.so"

# status codes of include/landyn.h
OK = 0
ERR_INPUT = 1
ERR_HANDLE = 2
ERR_ORDER = 3
ERR_FAILED = 4
ERR_FILE = 5
ENDED = 6


def _checkout_root() -> Optional[Path]:
    """The source checkout this package belongs to (an editable install or a source tree), if any.

    The package lives in <checkout>/python/landyn; a checkout is recognised by include/landyn.h.
    """
    root = Path(__file__).resolve().parent.parent.parent
    return root if (root / "include" / "landyn.h").is_file() else None


def candidates() -> List[Path]:
    """Where the library is looked for, in order (LANDYN_LIBRARY first, then the checkout's builds)."""
    out: List[Path] = []
    env = os.environ.get("LANDYN_LIBRARY")
    if env:
        p = Path(env).expanduser()
        out.append(p / LIBRARY_NAME if p.is_dir() else p)
    root = _checkout_root()
    if root is not None:
        out += [root / "build" / "release" / LIBRARY_NAME, root / "build" / "debug" / LIBRARY_NAME]
    return out


def library_path() -> str:
    """The path of the liblandyn.so this process uses (LandynLibraryError when there is none).

    Searched in order: the environment variable LANDYN_LIBRARY (the file, or a directory holding it;
    when set it must exist: no fall-back hides a wrong setting), the build trees build/release and
    build/debug of the source checkout the package was installed from (pip install -e python/), then
    the system's library path (ldconfig).
    """
    env = os.environ.get("LANDYN_LIBRARY")
    searched = candidates()
    if env:
        if searched[0].is_file():
            return str(searched[0])
        raise LandynLibraryError(f"LANDYN_LIBRARY={env!r}: {searched[0]} does not exist (a path to "
                                 f"{LIBRARY_NAME}, or a directory holding it, was expected)")
    for p in searched:
        if p.is_file():
            return str(p)
    system = ctypes.util.find_library("landyn")
    if system:
        return system
    where = ", ".join(str(p) for p in searched) or "(the package is not in a source checkout)"
    raise LandynLibraryError(
        f"{LIBRARY_NAME} not found. Searched: LANDYN_LIBRARY (not set), {where}, the system's library path. "
        f"Build it (bash scripts/build.sh in the checkout) or set LANDYN_LIBRARY to its path.")


def _prototype(lib: ctypes.CDLL) -> ctypes.CDLL:
    """Declares the argument and result types of every function of include/landyn.h."""
    c_char_p, c_void_p, c_int, c_size_t, c_double = (ctypes.c_char_p, ctypes.c_void_p, ctypes.c_int,
                                                     ctypes.c_size_t, ctypes.c_double)
    p_double, p_int, pp_void = ctypes.POINTER(c_double), ctypes.POINTER(c_int), ctypes.POINTER(c_void_p)
    protos = {
        "landyn_version": ([], c_char_p),
        "landyn_create": ([c_char_p, c_char_p, pp_void, c_char_p, c_size_t], c_int),
        "landyn_create_named": ([c_char_p, c_char_p, c_char_p, pp_void, c_char_p, c_size_t], c_int),
        "landyn_free": ([pp_void], c_int),
        "landyn_set_input": ([c_void_p, p_double, p_double, c_char_p, c_size_t], c_int),
        "landyn_advance_to": ([c_void_p, c_double, c_char_p, c_size_t], c_int),
        "landyn_time": ([c_void_p, p_double], c_int),
        "landyn_output_count": ([c_void_p, p_int], c_int),
        "landyn_output_info": ([c_void_p, c_int, c_char_p, c_size_t, c_char_p, c_size_t, c_char_p, c_size_t],
                               c_int),
        "landyn_get_outputs": ([c_void_p, p_double, c_int, c_char_p, c_size_t], c_int),
        "landyn_get_output": ([c_void_p, c_char_p, p_double, c_char_p, c_size_t], c_int),
        "landyn_write_result": ([c_void_p, c_char_p, c_char_p, c_size_t], c_int),
    }
    for name, (args, res) in protos.items():
        try:
            fn = getattr(lib, name)
        except AttributeError as exc:
            raise LandynLibraryError(f"{lib._name}: the function {name} of include/landyn.h is missing "
                                     f"(a library older than this package?)") from exc
        fn.argtypes, fn.restype = args, res
    return lib


@functools.lru_cache(maxsize=None)
def _load(path: str) -> ctypes.CDLL:
    try:
        lib = ctypes.CDLL(path)
    except OSError as exc:
        raise LandynLibraryError(f"{path}: cannot be loaded: {exc}") from exc
    return _prototype(lib)


def load() -> ctypes.CDLL:
    """The loaded library with its prototypes (loaded once per process and path)."""
    return _load(library_path())

"""Shared command-line plumbing: headless matplotlib, one-line errors, exit codes.

Exit status of every tool, consistent with ``landyn``'s (docs: post/README.md, docs/exit_status.md):
0 success; 1 usage error (bad or conflicting options); 2 invalid input (missing file, not HDF5,
wrong schema, missing dataset, malformed CSV or map, a damaged file); 4 an output file could not be
written or is refused by the output-file policy of docs/files.md; landyn-compare also: 3 a check
failed, 5 nothing was checked. Errors are reported as one line ``<tool>: error: <message>`` on
stderr, no traceback (set LANDYN_POST_TRACEBACK=1 to see one for an unexpected error).

Output-file policy (as the Fortran programs', docs/files.md): every file is written under a
temporary name in its directory and renamed when complete; an existing file is replaced only when it
is a writable regular file that is not HDF5 (a figure, a CSV); inputs of the run, directories,
devices, fifos, read-only files and HDF5 files are refused (exit 4) before anything is written.
"""
from __future__ import annotations

import argparse
import os
import sys

import contextlib
import tempfile

from . import files
from .schema import LandynPostError

EXIT_OK, EXIT_USAGE, EXIT_ERROR, EXIT_CHECK_FAILED, EXIT_WRITE, EXIT_NOTHING_CHECKED = 0, 1, 2, 3, 4, 5


class LandynUsageError(LandynPostError):
    """Options that do not fit together or do not fit the input (exit status 1)."""


class LandynWriteError(LandynPostError):
    """An output file could not be written (exit status 4)."""


def use_agg() -> None:
    """Selects matplotlib's headless Agg backend (call before importing pyplot)."""
    os.environ.setdefault("MPLBACKEND", "Agg")
    import matplotlib
    matplotlib.use("Agg", force=True)


class ArgumentParser(argparse.ArgumentParser):
    """argparse with the tools' error format (exit 1, one line)."""

    def error(self, message):
        self.print_usage(sys.stderr)
        self.exit(EXIT_USAGE, f"{self.prog}: error: {message}\n")


def _int_at_least(text: str, low: int) -> int:
    """An integer >= low from an option's text, or argparse's type error."""
    try:
        v = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"invalid integer: {text!r}") from None
    if v < low:
        raise argparse.ArgumentTypeError(f"must be >= {low}, got {v}")
    return v


def positive_int(text: str) -> int:
    """argparse type: an integer >= 1 (--dpi, --frames)."""
    return _int_at_least(text, 1)


def nonnegative_int(text: str) -> int:
    """argparse type: an integer >= 0 (--bins: 0 = automatic)."""
    return _int_at_least(text, 0)


def positive_float(text: str) -> float:
    """argparse type: a finite real number > 0 (--fps)."""
    try:
        v = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"invalid number: {text!r}") from None
    if not (v > 0 and v < float("inf")):
        raise argparse.ArgumentTypeError(f"must be a finite number > 0, got {text}")
    return v


def figure_format(path: str) -> str:
    """The figure format of a file name's extension; LandynUsageError when matplotlib cannot write it."""
    fmt = os.path.splitext(path)[1].lstrip(".").lower() or "png"
    from matplotlib.figure import Figure
    supported = Figure().canvas.get_supported_filetypes()
    if fmt not in supported:
        raise LandynUsageError(f"{path}: cannot write a figure as .{fmt}; use one of "
                               f"{', '.join('.' + k for k in sorted(supported))}")
    return fmt


def make_parser(prog: str, description: str, epilog: str | None = None) -> ArgumentParser:
    return ArgumentParser(prog=prog, description=description, epilog=epilog,
                          formatter_class=argparse.RawDescriptionHelpFormatter)


def run(prog: str, func, argv=None) -> int:
    """Runs func(argv) and maps user-facing errors to a one-line message and exit status 2."""
    try:
        return func(argv)
    except LandynWriteError as exc:
        print(f"{prog}: error: {exc}", file=sys.stderr)
        return EXIT_WRITE
    except LandynUsageError as exc:
        print(f"{prog}: error: {exc}", file=sys.stderr)
        return EXIT_USAGE
    except LandynPostError as exc:
        print(f"{prog}: error: {exc}", file=sys.stderr)
        return EXIT_ERROR
    except (FileNotFoundError, PermissionError, IsADirectoryError, NotADirectoryError) as exc:
        name = exc.filename or ""
        print(f"{prog}: error: {name}: {exc.strerror}" if name else f"{prog}: error: {exc}", file=sys.stderr)
        return EXIT_ERROR
    except KeyboardInterrupt:
        print(f"{prog}: interrupted", file=sys.stderr)
        return 130
    except Exception as exc:   # noqa: BLE001 - the promise is one line, never a traceback
        # What the readers did not turn into a LandynPostError: a damaged or truncated HDF5 file
        # (OSError, KeyError from h5py), data of the wrong type or with NaN where numbers belong
        # (ValueError, TypeError, IndexError), a text file in another encoding (UnicodeError).
        if os.environ.get("LANDYN_POST_TRACEBACK"):
            raise
        text = " ".join(str(exc).split()) or "no details"
        print(f"{prog}: error: cannot process the input ({type(exc).__name__}: {text}); is it a complete, "
              f"undamaged file of the kind this tool reads?", file=sys.stderr)
        return EXIT_ERROR


def output_dir(path: str) -> str:
    """Creates (if needed) and returns an output directory."""
    why = output_problem(path, directory=True)
    if why:
        raise LandynWriteError(why)
    try:
        os.makedirs(path, exist_ok=True)
    except OSError as exc:
        raise LandynWriteError(f"cannot create output directory {path}: {exc.strerror}") from None
    return path


def refuse_overwrite(out: str, inputs, hdf5: bool = False) -> None:
    """Raises LandynWriteError (exit 4) when the output path is one of the input files, also through
    a link or another name (never overwrite input), or is otherwise refused by output_problem
    (hdf5: the output is an HDF5 file)."""
    for p in inputs:
        if p and os.path.exists(out) and os.path.exists(p) and os.path.samefile(out, p):
            raise LandynWriteError(f"{out}: is an input file; refusing to overwrite it (choose another output name)")
    # an existing directory is an output directory here (--tables DIR, --plots DIR): output_dir
    # checks it; a file written where a directory is would be refused by atomic_output
    why = "" if os.path.isdir(out) else output_problem(out, hdf5=hdf5)
    if why:
        raise LandynWriteError(why)


_HDF5_SIGNATURE = b"\x89HDF\r\n\x1a\n"


def output_problem(path: str, directory: bool = False, hdf5: bool = False) -> str:
    """Why the output `path` may not be written ('' when it may): the policy of docs/files.md.

    A missing name is fine; an existing one must be a writable regular file (a directory with
    directory=True) that is not an HDF5 file: a figure or a table never replaces a result, a study
    or a campaign, and nothing is written into a device, a fifo or a read-only file. An HDF5 output
    (hdf5=True: the XDMF mesh file) replaces only an HDF5 file, as the Fortran programs' results.
    """
    if not path or not path.strip():
        return "empty output file name"
    if not os.path.lexists(path):
        return ""
    if directory:
        if os.path.isdir(path):
            return ""
        return f"{path}: exists and is not a directory; refusing to replace it"
    if os.path.isdir(path):
        return f"{path}: is a directory; refusing to write a file there"
    if not os.path.exists(path):      # a dangling link: replaced by the rename, its target untouched
        return ""
    import stat
    st = os.stat(path)
    if not stat.S_ISREG(st.st_mode):
        return f"{path}: exists and is not a regular file (a device, fifo or socket); refusing to write to it"
    if not st.st_mode & (stat.S_IWUSR | stat.S_IWGRP | stat.S_IWOTH):
        return f"{path}: exists and is read-only; refusing to replace it"
    try:
        with open(path, "rb") as fh:
            head = fh.read(8)
    except OSError as exc:
        return f"{path}: cannot examine it ({exc.strerror})"
    if hdf5 and head != _HDF5_SIGNATURE:
        return f"{path}: exists and is not an HDF5 file; refusing to replace it"
    if not hdf5 and head == _HDF5_SIGNATURE:
        return f"{path}: exists and is an HDF5 file (a result, study or campaign?); refusing to replace it"
    return ""


@contextlib.contextmanager
def atomic_output(path: str, mode: str = "w", hdf5: bool = False, **kw):
    """Writes `path` under a temporary name in the same directory and renames it when the block
    completes, so that a file named `path` is always complete. Yields an open file (mode 'w'/'wb')
    or, with mode=None, the temporary path for writers that open files themselves. hdf5: the file
    written is HDF5 (output_problem)."""
    why = output_problem(path, hdf5=hdf5)
    if why:
        raise LandynWriteError(why)
    d = os.path.dirname(os.path.abspath(path))
    try:
        os.makedirs(d, exist_ok=True)
        fd, tmp = tempfile.mkstemp(prefix="." + os.path.basename(path) + ".", suffix=".partial", dir=d)
        os.close(fd)
        files.follow_umask(tmp)      # mkstemp's 0600 -> the umask's mode (0644 under umask 022)
    except OSError as exc:
        raise LandynWriteError(f"cannot write {path}: {exc.strerror}") from None
    try:
        if mode is None:
            yield tmp
        else:
            with open(tmp, mode, **kw) as fh:
                yield fh
        os.replace(tmp, path)
    except OSError as exc:
        with contextlib.suppress(OSError):
            os.remove(tmp)
        raise LandynWriteError(f"cannot write {path}: {exc.strerror or exc}") from None
    except BaseException:
        with contextlib.suppress(OSError):
            os.remove(tmp)
        raise


def savefig(fig, path: str, **kw) -> str:
    """fig.savefig through a temporary file and a rename; returns path."""
    fmt = figure_format(path)
    with atomic_output(path, mode=None) as tmp:
        fig.savefig(tmp, format=fmt, **kw)
    return path


def stem(path: str) -> str:
    """File name without directory and extension."""
    return os.path.splitext(os.path.basename(path))[0]

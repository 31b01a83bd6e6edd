"""Shared command-line plumbing: headless matplotlib, one-line errors, exit codes.

Exit status of every tool, consistent with ``landyn``'s (docs: post/README.md):
0 success; 1 usage error (bad or conflicting options); 2 invalid input (missing file, not HDF5,
wrong schema, missing dataset, malformed CSV or map); 4 an output file could not be written;
landyn-compare also: 3 a check failed, 5 nothing was checked. Errors are reported as one line
``<tool>: error: <message>`` on stderr, no traceback.
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
    """argparse with the tools' error format (exit 2, one line)."""

    def error(self, message):
        self.print_usage(sys.stderr)
        self.exit(EXIT_USAGE, f"{self.prog}: error: {message}\n")


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


def output_dir(path: str) -> str:
    """Creates (if needed) and returns an output directory."""
    try:
        os.makedirs(path, exist_ok=True)
    except OSError as exc:
        raise LandynWriteError(f"cannot create output directory {path}: {exc.strerror}") from None
    return path


def refuse_overwrite(out: str, inputs) -> None:
    """Raises LandynPostError when the output path is one of the input files (never overwrite input)."""
    for p in inputs:
        if p and os.path.exists(out) and os.path.exists(p) and os.path.samefile(out, p):
            raise LandynPostError(f"{out}: is an input file; refusing to overwrite it (choose another output name)")


@contextlib.contextmanager
def atomic_output(path: str, mode: str = "w", **kw):
    """Writes `path` under a temporary name in the same directory and renames it when the block
    completes, so that a file named `path` is always complete. Yields an open file (mode 'w'/'wb')
    or, with mode=None, the temporary path for writers that open files themselves."""
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
    fmt = os.path.splitext(path)[1].lstrip(".") or "png"
    with atomic_output(path, mode=None) as tmp:
        fig.savefig(tmp, format=fmt, **kw)
    return path


def stem(path: str) -> str:
    """File name without directory and extension."""
    return os.path.splitext(os.path.basename(path))[0]

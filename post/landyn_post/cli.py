"""Shared command-line plumbing: headless matplotlib, one-line errors, exit codes.

Exit status of every tool: 0 success; 1 a check failed (landyn-compare tolerances);
2 usage or input error (bad option, missing file, not HDF5, wrong schema, missing dataset,
malformed CSV) -- reported as one line ``<tool>: error: <message>`` on stderr, no traceback.
"""
from __future__ import annotations

import argparse
import os
import sys

from .schema import LandynPostError

EXIT_OK, EXIT_CHECK_FAILED, EXIT_ERROR = 0, 1, 2


def use_agg() -> None:
    """Selects matplotlib's headless Agg backend (call before importing pyplot)."""
    os.environ.setdefault("MPLBACKEND", "Agg")
    import matplotlib
    matplotlib.use("Agg", force=True)


class ArgumentParser(argparse.ArgumentParser):
    """argparse with the tools' error format (exit 2, one line)."""

    def error(self, message):
        self.print_usage(sys.stderr)
        self.exit(EXIT_ERROR, f"{self.prog}: error: {message}\n")


def make_parser(prog: str, description: str, epilog: str | None = None) -> ArgumentParser:
    return ArgumentParser(prog=prog, description=description, epilog=epilog,
                          formatter_class=argparse.RawDescriptionHelpFormatter)


def run(prog: str, func, argv=None) -> int:
    """Runs func(argv) and maps user-facing errors to a one-line message and exit status 2."""
    try:
        return func(argv)
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
        raise LandynPostError(f"cannot create output directory {path}: {exc.strerror}") from None
    return path


def stem(path: str) -> str:
    """File name without directory and extension."""
    return os.path.splitext(os.path.basename(path))[0]

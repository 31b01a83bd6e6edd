"""File modes of the tools' output: every file follows the user's umask, as ``landyn``'s HDF5 does.

``tempfile.mkstemp`` (used to write each output under a temporary name, see
``cli.atomic_output``) creates its file with mode 0600 whatever the umask, so colleagues on a
shared disk could not read a figure or a table. ``follow_umask(path)`` gives a file the mode an
ordinary ``open(path, 'w')`` would have given it: 0666 masked by the process umask (0644 under
the usual umask 022, 0640 under 027).
"""
from __future__ import annotations

import os

_CREATE_MODE = 0o666   #: what open() and h5py ask for; the umask removes bits from it


def current_umask() -> int:
    """The process umask, read from /proc/self/status where available (no change to the process
    state), else by setting and restoring it."""
    try:
        with open("/proc/self/status", encoding="ascii") as fh:
            for line in fh:
                if line.startswith("Umask:"):
                    return int(line.split()[1], 8)
    except (OSError, ValueError, IndexError):
        pass
    mask = os.umask(0o022)
    os.umask(mask)
    return mask


def default_mode() -> int:
    """Mode of a new regular file under the current umask, e.g. 0o644 for umask 022."""
    return _CREATE_MODE & ~current_umask()


def follow_umask(path: str) -> None:
    """Sets the mode of `path` (a file this process created) to default_mode()."""
    os.chmod(path, default_mode())

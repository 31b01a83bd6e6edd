/* landyn_fileinfo: the one POSIX call Fortran 2008 has no equivalent for, stat(2), for the
 * output-file policy of landyn_files (refuse to overwrite an input, a non-regular file or a
 * read-only file). Called through bind(C) from src/landyn_files.f90; nothing else. */
#include <sys/stat.h>
#include <errno.h>

/* kind: 0 no such file, 1 regular file, 2 directory, 3 anything else (device, fifo, socket),
 *       -1 cannot tell (permission denied on the way, name too long, ...).
 * dev, ino: identity of the file (same file <=> same dev and ino), 0 when kind <= 0.
 * writable: 1 when some write permission bit is set (root ignores the bits, we do not). */
void landyn_file_info(const char *path, int *kind, long long *dev, long long *ino, int *writable)
{
    struct stat st;
    *kind = 0;
    *dev = 0;
    *ino = 0;
    *writable = 0;
    if (stat(path, &st) != 0) {
        *kind = (errno == ENOENT || errno == ENOTDIR) ? 0 : -1;
        return;
    }
    if (S_ISREG(st.st_mode))
        *kind = 1;
    else if (S_ISDIR(st.st_mode))
        *kind = 2;
    else
        *kind = 3;
    *dev = (long long)st.st_dev;
    *ino = (long long)st.st_ino;
    *writable = (st.st_mode & (S_IWUSR | S_IWGRP | S_IWOTH)) != 0;
}

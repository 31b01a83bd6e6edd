/* landyn_fileinfo: the POSIX calls Fortran 2008 has no equivalent for: stat(2), for the
 * output-file policy of landyn_files (refuse to overwrite an input, a non-regular file or a
 * read-only file), and flock(2), for the lock that keeps two processes off one campaign.
 * Called through bind(C) from src/core/landyn_files.f90; nothing else. */
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

/* An advisory lock held for the life of the process (flock(2), so the kernel releases it when the
 * process ends, also when it is killed; no stale lock is ever left behind to clear by hand).
 * Opens (creating, mode 0666 less the umask) `path`, locks it exclusively without waiting, and
 * checks that `path` still names the locked file (another process may have removed it while we
 * waited for the open): then retries. Writes our pid into it.
 * Returns 0 and *fd on success; 1 when another process holds it (*holder = its pid, or 0 if
 * unknown); -1 when the file cannot be opened or locked (errno kept). */
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/file.h>
#include <unistd.h>

int landyn_lock_file(const char *path, int *fd, long long *holder)
{
    *fd = -1;
    *holder = 0;
    for (int attempt = 0; attempt < 100; attempt++) {
        int f = open(path, O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW, 0666);
        if (f < 0)
            return -1;
        if (flock(f, LOCK_EX | LOCK_NB) != 0) {
            int busy = (errno == EWOULDBLOCK);
            if (busy) {
                char buf[32] = {0};
                ssize_t n = pread(f, buf, sizeof buf - 1, 0);
                if (n > 0)
                    *holder = atoll(buf);
            }
            close(f);
            return busy ? 1 : -1;
        }
        struct stat a, b;
        if (fstat(f, &a) == 0 && stat(path, &b) == 0 && a.st_dev == b.st_dev && a.st_ino == b.st_ino) {
            char buf[32];
            int n = snprintf(buf, sizeof buf, "%ld\n", (long)getpid());
            if (ftruncate(f, 0) != 0 || pwrite(f, buf, (size_t)n, 0) != n) {
                /* the pid is only a courtesy for the message of a refused process */
            }
            *fd = f;
            return 0;
        }
        close(f);   /* removed or replaced meanwhile: lock the file that is there now */
    }
    return -1;
}

/* Remove the lock file (while still holding the lock, so that no process can take the old one)
 * and release it. */
void landyn_unlock_file(const char *path, int fd)
{
    if (fd < 0)
        return;
    unlink(path);
    close(fd);
}

/* An injected full disk for the store's fault tests (tests/study/test_store_faults.cpp), loaded
 * with LD_PRELOAD into a ccm process: write, writev, pwrite and pwrite64 on files under the
 * folder CCM_TEST_DISK_DIR succeed until CCM_TEST_DISK_BYTES bytes have been written there, then
 * fail with ENOSPC, as a file system that fills up does. With CCM_TEST_DISK_REPORT set, the bytes
 * written there are appended to that file at exit (how much a run writes, to place the fault). */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/types.h>
#include <sys/uio.h>
#include <unistd.h>

static unsigned long long written = 0;

/* Whether fd is a file under CCM_TEST_DISK_DIR. */
static int watched(int fd) {
  const char* dir = getenv("CCM_TEST_DISK_DIR");
  if (!dir || !*dir) return 0;
  char link[64], path[4096];
  snprintf(link, sizeof link, "/proc/self/fd/%d", fd);
  const ssize_t n = readlink(link, path, sizeof path - 1);
  if (n <= 0) return 0;
  path[n] = '\0';
  return strncmp(path, dir, strlen(dir)) == 0;
}

/* 0 when `count` more bytes fit the budget (and books them), else -1 with errno ENOSPC. */
static int book(int fd, size_t count) {
  if (!watched(fd)) return 0;
  const char* budget = getenv("CCM_TEST_DISK_BYTES");
  if (budget && written + count > strtoull(budget, NULL, 10)) {
    errno = ENOSPC;
    return -1;
  }
  written += count;
  return 0;
}

__attribute__((destructor)) static void report(void) {
  const char* file = getenv("CCM_TEST_DISK_REPORT");
  if (!file) return;
  FILE* out = fopen(file, "a");
  if (!out) return;
  fprintf(out, "%llu\n", written);
  fclose(out);
}

#define NEXT(name) ((__typeof__(&name))dlsym(RTLD_NEXT, #name))

ssize_t write(int fd, const void* buf, size_t count) {
  if (book(fd, count) < 0) return -1;
  return NEXT(write)(fd, buf, count);
}

ssize_t pwrite(int fd, const void* buf, size_t count, off_t offset) {
  if (book(fd, count) < 0) return -1;
  return NEXT(pwrite)(fd, buf, count, offset);
}

ssize_t pwrite64(int fd, const void* buf, size_t count, off64_t offset) {
  if (book(fd, count) < 0) return -1;
  return NEXT(pwrite64)(fd, buf, count, offset);
}

ssize_t writev(int fd, const struct iovec* iov, int n) {
  size_t count = 0;
  for (int i = 0; i < n; ++i) count += iov[i].iov_len;
  if (book(fd, count) < 0) return -1;
  return NEXT(writev)(fd, iov, n);
}

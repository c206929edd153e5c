// The floor under `arbiter check` of many files in bench/compare-arb.sh: what reading them
// costs and nothing else (open, fstat, one read, close per file, as arbiter reads a file).
// Prints the number of bytes read. Usage: read_files FILE...
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdio>
#include <string>

int main(int argc, char** argv) {
  std::string bytes;
  size_t total = 0;
  for (int i = 1; i < argc; ++i) {
    const int fd = ::open(argv[i], O_RDONLY | O_CLOEXEC);
    struct stat info {};
    if (fd < 0 || ::fstat(fd, &info) != 0) {
      std::perror(argv[i]);
      return 1;
    }
    bytes.resize(static_cast<size_t>(info.st_size) + 1);
    const ssize_t count = ::read(fd, bytes.data(), bytes.size());
    ::close(fd);
    if (count < 0) {
      std::perror(argv[i]);
      return 1;
    }
    total += static_cast<size_t>(count);
  }
  std::printf("%zu bytes\n", total);
  return 0;
}

// SPDX-License-Identifier: GPL-3.0-or-later
// The harnesses' main outside libFuzzer (the default gcc build, registered with ctest): runs
// LLVMFuzzerTestOneInput on every file given (directories recursively, in name order), then,
// with --mutations N, on N seeded mutations of each (bit flips, byte insertions, deletions,
// repeats and splices of two inputs): a smoke run of seconds over the seed corpus. A crash or a
// broken FUZZ_CHECK aborts and names the input. Missing paths are skipped (the third-party
// corpus under ../shared may be absent).
// Usage: HARNESS [--mutations N] [--seed S] [--max-len BYTES] PATH...
#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);
extern "C" int LLVMFuzzerInitialize(int* argc, char*** argv) __attribute__((weak));

namespace {

using Bytes = std::vector<std::uint8_t>;
namespace fs = std::filesystem;

// The input being run, written to fuzz-replay-crash.bin (in the working directory) when it
// aborts or crashes, so that a mutant's finding can be replayed and kept as a regression.
const Bytes* gCurrent = nullptr;

void saveCurrent(int signal) {
  if (gCurrent) {
    const int fd = ::open("fuzz-replay-crash.bin", O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (fd >= 0) {
      const ssize_t written = ::write(fd, gCurrent->data(), gCurrent->size());
      (void)written;
      ::close(fd);
    }
    static const char kSaved[] = "the input is in fuzz-replay-crash.bin\n";
    const ssize_t said = ::write(2, kSaved, sizeof kSaved - 1);
    (void)said;
  }
  std::signal(signal, SIG_DFL);
  std::raise(signal);
}

void run(const Bytes& input) {
  gCurrent = &input;
  LLVMFuzzerTestOneInput(input.data(), input.size());
  gCurrent = nullptr;
}

Bytes readAll(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return Bytes(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

Bytes mutate(const Bytes& input, const Bytes& other, std::mt19937_64& rng, std::size_t maxLen) {
  Bytes out = input;
  const int edits = 1 + static_cast<int>(rng() % 4);
  for (int e = 0; e < edits; ++e) {
    const std::size_t at = out.empty() ? 0 : rng() % out.size();
    switch (rng() % 6) {
      case 0:
        if (!out.empty()) out[at] ^= static_cast<std::uint8_t>(1u << (rng() % 8));
        break;
      case 1: out.insert(out.begin() + static_cast<long>(at), static_cast<std::uint8_t>(rng())); break;
      case 2:
        if (!out.empty()) out.erase(out.begin() + static_cast<long>(at));
        break;
      case 3: {  // an interesting byte: digits, signs, separators and markup
        static const char kBytes[] = "0123456789-+.eE,;: <>/\"=\n\r\t\\#$%[]{}";
        if (!out.empty()) out[at] = static_cast<std::uint8_t>(kBytes[rng() % (sizeof kBytes - 1)]);
        break;
      }
      case 4: {  // repeat a slice
        if (out.empty()) break;
        const std::size_t len = 1 + rng() % std::min<std::size_t>(out.size() - at, 64);
        Bytes slice(out.begin() + static_cast<long>(at), out.begin() + static_cast<long>(at + len));
        out.insert(out.begin() + static_cast<long>(at), slice.begin(), slice.end());
        break;
      }
      default: {  // splice another input in
        if (other.empty()) break;
        const std::size_t from = rng() % other.size();
        const std::size_t len = 1 + rng() % std::min<std::size_t>(other.size() - from, 256);
        out.insert(out.begin() + static_cast<long>(at), other.begin() + static_cast<long>(from),
                   other.begin() + static_cast<long>(from + len));
        break;
      }
    }
  }
  if (out.size() > maxLen) out.resize(maxLen);
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  if (LLVMFuzzerInitialize) LLVMFuzzerInitialize(&argc, &argv);
  for (int signal : {SIGABRT, SIGSEGV, SIGBUS, SIGFPE, SIGILL}) std::signal(signal, saveCurrent);
  long mutations = 0;
  std::uint64_t seed = 1;
  std::size_t maxLen = 1 << 20;
  std::vector<fs::path> files;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--mutations" && i + 1 < argc) mutations = std::atol(argv[++i]);
    else if (a == "--seed" && i + 1 < argc) seed = std::strtoull(argv[++i], nullptr, 10);
    else if (a == "--max-len" && i + 1 < argc) maxLen = std::strtoull(argv[++i], nullptr, 10);
    else if (fs::is_directory(a)) {
      std::vector<fs::path> found;
      for (const auto& entry : fs::recursive_directory_iterator(a))
        if (entry.is_regular_file()) found.push_back(entry.path());
      std::sort(found.begin(), found.end());
      files.insert(files.end(), found.begin(), found.end());
    } else if (fs::is_regular_file(a)) {
      files.emplace_back(a);
    } else {
      std::fprintf(stderr, "skipped (not found): %s\n", a.c_str());
    }
  }
  std::vector<Bytes> inputs;
  for (const fs::path& f : files) {
    Bytes bytes = readAll(f);
    if (bytes.size() > maxLen) continue;  // the fuzzer's own -max_len: a smoke run stays short
    std::fprintf(stderr, "input %s\n", f.c_str());
    run(bytes);
    inputs.push_back(std::move(bytes));
  }
  std::mt19937_64 rng(seed);
  long runs = static_cast<long>(inputs.size());
  for (std::size_t i = 0; i < inputs.size() && mutations > 0; ++i) {
    for (long m = 0; m < mutations; ++m) {
      const Bytes& other = inputs[rng() % inputs.size()];
      const Bytes mutant = mutate(inputs[i], other, rng, maxLen);
      run(mutant);
      ++runs;
    }
  }
  std::printf("%zu inputs, %ld runs (seed %llu), no finding\n", inputs.size(), runs,
              static_cast<unsigned long long>(seed));
  return inputs.empty() ? 1 : 0;
}

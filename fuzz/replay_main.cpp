// The main() of a fuzz target built without libFuzzer (any compiler; the normal Release build):
// feeds every file of the given directories (and every given file) to LLVMFuzzerTestOneInput once,
// in name order, so ctest replays the seed corpus and every saved finding with the suite.
//
//   fuzz-<target> [--max-ms N] CORPUS_DIR|FILE...
//
// Exit status 0 when every input ran (a finding aborts the program); 1 when there was no input at
// all (an empty or misspelled corpus would otherwise pass) or an input took longer than --max-ms.
#include "fuzz/fuzz_target.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

std::vector<fs::path> inputsOf(const fs::path& arg)
{
    std::vector<fs::path> files;
    if (fs::is_directory(arg)) {
        for (const auto& entry : fs::directory_iterator(arg))
            if (entry.is_regular_file()) files.push_back(entry.path());
        std::sort(files.begin(), files.end());
    } else if (fs::is_regular_file(arg)) {
        files.push_back(arg);
    } else {
        std::fprintf(stderr, "replay: no such file or directory: %s\n", arg.c_str());
    }
    return files;
}

}  // namespace

int main(int argc, char** argv)
{
    double maxMs = 0.0;  // 0: no limit
    std::vector<fs::path> files;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--max-ms" && i + 1 < argc) {
            maxMs = std::stod(argv[++i]);
            continue;
        }
        const std::vector<fs::path> found = inputsOf(arg);
        files.insert(files.end(), found.begin(), found.end());
    }
    if (files.empty()) {
        std::fprintf(stderr, "replay: no inputs (usage: %s [--max-ms N] CORPUS_DIR|FILE...)\n", argv[0]);
        return 1;
    }
    double slowestMs = 0.0;
    fs::path slowest;
    for (const fs::path& file : files) {
        std::ifstream in(file, std::ios::binary);
        const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        const auto start = std::chrono::steady_clock::now();
        LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
        const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        if (ms > slowestMs) {
            slowestMs = ms;
            slowest = file;
        }
    }
    std::printf("replay: %zu inputs, slowest %.1f ms (%s)\n", files.size(), slowestMs, slowest.c_str());
    if (maxMs > 0.0 && slowestMs > maxMs) {
        std::fprintf(stderr, "replay: %s took %.1f ms, over the limit of %.0f ms (a hang)\n", slowest.c_str(), slowestMs, maxMs);
        return 1;
    }
    return 0;
}

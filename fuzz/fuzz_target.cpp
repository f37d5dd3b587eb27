#include "fuzz/fuzz_target.h"

#include <cstdio>
#include <cstdlib>

namespace sculptline::fuzz {

void fuzzFailure(const std::string& what, const std::string& detail)
{
    std::fprintf(stderr, "fuzz finding: %s: %s\n", what.c_str(), detail.c_str());
    std::fflush(stderr);
    std::abort();
}

void noteRejected(const std::string& why)
{
    static const bool verbose = std::getenv("SCULPTLINE_FUZZ_VERBOSE") != nullptr;
    if (verbose) std::fprintf(stderr, "rejected: %s\n", why.c_str());
}

}  // namespace sculptline::fuzz

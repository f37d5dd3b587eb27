#pragma once
// What every fuzz target shares: the libFuzzer entry point and the way a finding is reported.
//
// A target returns normally for accepted and for rejected input (the InputError or GeometryError
// that makes sculptline-cli exit with status 2); anything else is a finding: an uncaught
// exception, a failed check (fuzzFailure), a crash, a sanitizer report, or a run over the time limit
// (libFuzzer's -timeout; replay_main's --max-ms).
#include <cstddef>
#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace sculptline::fuzz {

/// Prints "fuzz finding: <what>: <detail>" to stderr and aborts, so that libFuzzer saves the input
/// as a crash artifact and a replay test fails.
[[noreturn]] void fuzzFailure(const std::string& what, const std::string& detail);

/// Rejected input: prints "rejected: <why>" when SCULPTLINE_FUZZ_VERBOSE is set (to see which seeds a
/// loader refuses), else nothing.
void noteRejected(const std::string& why);

}  // namespace sculptline::fuzz

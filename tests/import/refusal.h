#pragma once
// What an .iv check refuses a text with, for the validator's and the importer's tests.
#include "scene/iv_validate.h"
#include "solvers/io/geometry_json.h"

#include <gtest/gtest.h>

#include <string>

namespace sculptline::test {

/// The message `check(text, limits)` refuses `text` with ("" when it accepts it).
template <class Check>
std::string refusal(Check check, const std::string& text, const scene::IvLimits& limits = {})
{
    try {
        check(text, limits);
    } catch (const solvers::io::InputError& e) {
        return e.what();
    }
    return "";
}

/// Expects `check` to refuse `text` with a message containing `expected`.
template <class Check>
void expectRefusedBy(Check check, const std::string& text, const std::string& expected, const scene::IvLimits& limits = {})
{
    const std::string message = refusal(check, text, limits);
    EXPECT_NE(message.find(expected), std::string::npos) << "refused with \"" << message << "\", expected \"" << expected << "\"";
}

}  // namespace sculptline::test

// The "references" member of a document (model/document.h ReferenceSpec): read as written, refused
// with the field named when malformed, absent = none. The files themselves are read by the GUI.
#include "model/document.h"

#include "solvers/io/geometry_json.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace {

using sculptline::model::documentFromJson;
using sculptline::solvers::io::InputError;

std::string refusal(const nlohmann::json& j)
{
    try {
        documentFromJson(j);
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

TEST(DocumentReferences, GivenReferences_WhenRead_ThenPathsKeptInOrder)
{
    const auto doc = documentFromJson(nlohmann::json::parse(
        R"({"references": [{"path": "/a/box.iv", "relative": "box.iv"}, {"path": "scan.iv"}]})"));
    ASSERT_EQ(doc.references.size(), 2u);
    EXPECT_EQ(doc.references[0].path, "/a/box.iv");
    EXPECT_EQ(doc.references[0].relative, "box.iv");
    EXPECT_EQ(doc.references[1].path, "scan.iv");
    EXPECT_EQ(doc.references[1].relative, "");
    EXPECT_TRUE(documentFromJson(nlohmann::json::object()).references.empty());
}

TEST(DocumentReferences, GivenMalformedReferences_ThenRefusedNamingTheField)
{
    EXPECT_EQ(refusal(nlohmann::json::parse(R"({"references": {}})")), "references: must be an array");
    EXPECT_EQ(refusal(nlohmann::json::parse(R"({"references": [3]})")), "references[0]: must be a JSON object");
    EXPECT_NE(refusal(nlohmann::json::parse(R"({"references": [{}]})")).find("references[0].path"), std::string::npos);
    EXPECT_EQ(refusal(nlohmann::json::parse(R"({"references": [{"path": ""}]})")), "references[0].path: must be a non-empty string");
    EXPECT_EQ(refusal(nlohmann::json::parse(R"({"references": [{"path": "a", "relative": 1}]})")),
              "references[0].relative: must be a non-empty string");
    nlohmann::json nul = {{"references", {{{"path", std::string("a\0b", 3)}}}}};
    EXPECT_EQ(refusal(nul), "references[0].path: must not contain a NUL character");
}

}  // namespace

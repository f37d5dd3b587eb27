// The text check of scene/iv_validate.h: one test per refusal, its message checked, and the census
// of accepted text. Given / When / Then.
#include "scene/iv_validate.h"

#include "solvers/io/geometry_json.h"

#include "refusal.h"

#include <gtest/gtest.h>

#include <string>

namespace {

using sculptline::scene::IvLimits;
using sculptline::scene::validateIvText;
using sculptline::solvers::io::InputError;

const std::string kHeader = "#Inventor V2.1 ascii\n\n";

std::string refusal(const std::string& text, const IvLimits& limits = {})
{
    return sculptline::test::refusal([](const std::string& t, const IvLimits& l) { validateIvText(t, l); }, text, limits);
}

void expectRefused(const std::string& text, const std::string& expected, const IvLimits& limits = {})
{
    sculptline::test::expectRefusedBy([](const std::string& t, const IvLimits& l) { validateIvText(t, l); }, text, expected, limits);
}

TEST(IvValidate, GivenPlainGeometry_WhenValidated_ThenCounted)
{
    const std::string text = kHeader +
                             "# a comment\nSeparator {\n  Coordinate3 { point [ 0 0 0, 1 0 0, 0 1 0, ] }\n"
                             "  IndexedFaceSet { coordIndex [ 0, 1, 2, -1 ] }\n  Cone { parts (SIDES | BOTTOM) height 2 }\n}\n";
    const auto census = validateIvText(text);
    EXPECT_EQ(census.nodes, 4u);
    EXPECT_EQ(census.coordinates, 3u);
    EXPECT_EQ(census.numbers, 9u + 4u + 1u);
    EXPECT_EQ(census.depth, 2);
}

TEST(IvValidate, GivenSoPrefixedTypes_WhenValidated_ThenAccepted)
{
    EXPECT_EQ(refusal(kHeader + "SoSeparator { SoCube { } }"), "");
}

TEST(IvValidate, GivenTextOverTheSizeLimit_ThenRefused)
{
    IvLimits limits;
    limits.maxBytes = 30;
    expectRefused(kHeader + "Separator { Cube { } }", "bytes, over the limit of 30 bytes", limits);
}

TEST(IvValidate, GivenNoHeader_ThenRefused) { expectRefused("Separator { Cube { } }", "not an Open Inventor ASCII file"); }
TEST(IvValidate, GivenBinaryHeader_ThenRefused) { expectRefused("#Inventor V2.1 binary\n", "binary Open Inventor is not accepted"); }
TEST(IvValidate, GivenVrml_ThenRefused) { expectRefused("#VRML V2.0 utf8\nShape {}", "VRML is not accepted"); }
TEST(IvValidate, GivenInventorV1_ThenRefused) { expectRefused("#Inventor V1.0 ascii\nCube {}", "only Open Inventor V2.0/V2.1 ASCII"); }

TEST(IvValidate, GivenDeepNesting_ThenRefused)
{
    std::string text = kHeader;
    for (int i = 0; i < 65; ++i) text += "Group { ";
    text += "Cube { }";
    for (int i = 0; i < 65; ++i) text += " }";
    expectRefused(text, "line 3: nodes nested deeper than 64 levels");
}

TEST(IvValidate, GivenMoreNodesThanTheLimit_ThenRefused)
{
    IvLimits limits;
    limits.maxNodes = 3;
    expectRefused(kHeader + "Group { Cube { } Cube { } Cube { } }", "more than 3 nodes", limits);
}

TEST(IvValidate, GivenMoreNumbersThanTheLimit_ThenRefused)
{
    IvLimits limits;
    limits.maxNumbers = 5;
    expectRefused(kHeader + "Coordinate3 { point [ 0 0 0, 1 1 1 ] }", "more than 5 numbers", limits);
}

TEST(IvValidate, GivenMoreCoordinatesThanTheLimit_ThenRefused)
{
    IvLimits limits;
    limits.maxCoordinates = 2;
    expectRefused(kHeader + "Coordinate3 { point [ 0 0 0, 1 1 1, 2 2 2 ] }", "more than 2 coordinates", limits);
}

TEST(IvValidate, GivenNodeOutsideTheAllowList_ThenRefused)
{
    expectRefused(kHeader + "Switch { Cube { } }", "line 3: node type Switch is not accepted");
    expectRefused(kHeader + "Separator {\n VertexProperty { } }", "line 4: node type VertexProperty is not accepted");
}

TEST(IvValidate, GivenNodesThatReadFiles_ThenRefused)
{
    expectRefused(kHeader + "Separator { File { name \"x.iv\" } }", "node File is not accepted: it reads files");
    expectRefused(kHeader + "Texture2 { filename \"x.png\" }", "node Texture2 is not accepted: it reads files");
    expectRefused(kHeader + "SoShaderProgram { }", "node ShaderProgram is not accepted");
}

TEST(IvValidate, GivenExternalReferences_ThenRefused)
{
    expectRefused(kHeader + "PROTO Box [ ] { Cube { } }", "PROTO is not accepted: external references and prototypes are refused");
    expectRefused(kHeader + "WWWInline { }", "WWWInline is not accepted");
}

TEST(IvValidate, GivenEngines_ThenRefused)
{
    expectRefused(kHeader + "ElapsedTimeEngine { }", "engine ElapsedTimeEngine is not accepted");
    expectRefused(kHeader + "Translation { translation 0 0 0 = ElapsedTime { } . timeOut }", "field connections (=) are not accepted");
}

TEST(IvValidate, GivenStrings_ThenRefused) { expectRefused(kHeader + "Cube { width \"1\" }", "strings are not accepted"); }

TEST(IvValidate, GivenDefUseCycle_ThenRefused)
{
    expectRefused(kHeader + "DEF A Separator { Cube { }\n USE A }", "line 4: USE A inside its own DEF (a cycle)");
}

TEST(IvValidate, GivenUseBeforeDef_ThenRefused) { expectRefused(kHeader + "Separator { USE B }", "USE B before any DEF B"); }

TEST(IvValidate, GivenUsesThatMultiplyBeyondTheBudget_ThenRefused)
{
    // 4^20 spheres in 1 kB.
    std::string text = kHeader + "DEF A Group { Sphere { } }\n";
    for (char c = 'B'; c < 'B' + 20; ++c) {
        const std::string prev(1, static_cast<char>(c - 1));
        text += "DEF " + std::string(1, c) + " Group { USE " + prev + " USE " + prev + " USE " + prev + " USE " + prev + " }\n";
    }
    expectRefused(text, "values to draw once every USE is expanded");
}

TEST(IvValidate, GivenUnknownField_ThenRefused) { expectRefused(kHeader + "Cube { size 2 }", "node Cube has no field size that is accepted"); }
TEST(IvValidate, GivenFieldDeclarations_ThenRefused) { expectRefused(kHeader + "Cube { fields [ SFFloat x ] }", "field declarations"); }

TEST(IvValidate, GivenVertexProperty_ThenRefused)
{
    expectRefused(kHeader + "FaceSet { vertexProperty VertexProperty { } }", "vertexProperty is not accepted (put the points in a Coordinate3 node)");
}

TEST(IvValidate, GivenNonFiniteNumbers_ThenRefused)
{
    expectRefused(kHeader + "Coordinate3 { point [ 0 0 0, nan 0 0 ] }", "expected a number, found \"nan\" (NaN and infinity are refused)");
    expectRefused(kHeader + "Coordinate3 { point [ -inf 0 0 ] }", "number -inf is not a finite float");
    expectRefused(kHeader + "Coordinate3 { point [ 1e39 0 0 ] }", "number 1e39 is not a finite float");
    expectRefused(kHeader + "Sphere { radius 1e999 }", "number 1e999 is out of range");
    expectRefused(kHeader + "Sphere { radius 1.2.3 }", "malformed number \"1.2.3\"");
    expectRefused(kHeader + "Cube { width 0x2 }", "malformed number \"0x2\"");  // Coin: Unknown field "x2"
}

TEST(IvValidate, GivenIntegersOutOfRange_ThenRefused)
{
    expectRefused(kHeader + "IndexedFaceSet { coordIndex [ 2147483648 ] }", "integer 2147483648 is out of range");
    expectRefused(kHeader + "IndexedFaceSet { coordIndex [ 0, -2 ] }", "integer -2 is out of range [-1, 2147483647]");
    expectRefused(kHeader + "IndexedFaceSet { coordIndex [ 0.5 ] }", "expected an integer, found \"0.5\"");
}

TEST(IvValidate, GivenUnknownEnumValue_ThenRefused)
{
    expectRefused(kHeader + "DrawStyle { style WIREFRAME }", "style: unknown value WIREFRAME");
    expectRefused(kHeader + "Complexity { type SCREEN_SPACE value 1 }", "type: unknown value SCREEN_SPACE");
}

TEST(IvValidate, GivenBinaryBytes_ThenRefused)
{
    expectRefused(kHeader + std::string("Cube {\0}", 8), "NUL byte");
    expectRefused(kHeader + "Cube { \x01 }", "unexpected character 0x01");
    expectRefused(kHeader + "Cube { width 1 ~ }", "unexpected character '~'");
}

TEST(IvValidate, GivenUnterminatedText_ThenRefused)
{
    expectRefused(kHeader + "Separator {\n Cube { }\n", "unterminated node Separator (opened on line 3)");
    expectRefused(kHeader + "Coordinate3 { point [ 0 0 0", "unterminated [ ... ] list");
    expectRefused(kHeader + "Cube { width }", "expected a number, found \"}\"");
}

TEST(IvValidate, GivenLongToken_ThenRefused)
{
    expectRefused(kHeader + "Cube { width 1" + std::string(80, '0') + " }", "a token longer than 64 characters");
}

}  // namespace

// sculptline-cli export (app/cli/cmd_export.cpp): Given JSON geometry, When the real binary exports
// it, Then the file is what the format's reader sees (OCCT for STEP/IGES, the bytes for STL/OBJ),
// the output names the path and the bytes written, and bad input exits 2 with one line naming the field.
#include "solvers/exchange/exchange.h"
#include "solvers/bspline/tessellation.h"
#include "solvers/io/geometry_json.h"
#include "tests/cli/cli_runner.h"
#include "tests/exchange/exchange_test_geometry.h"

#include <BRep_Tool.hxx>
#include <Geom_BSplineSurface.hxx>
#include <IGESControl_Reader.hxx>
#include <STEPControl_Reader.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <functional>

namespace sculptline::exchange_test {
namespace {

using cli_test::json;
using cli_test::runCli;
using cli_test::runOk;
using cli_test::scratchPath;

/// As in cad_round_trip_test: the exact geometry comes back up to the text's 17 digits.
constexpr double kExactRoundTrip = 1e-9;

json geometry()
{
    json in;
    in["curves"] = json::array({solvers::io::toJson(quarterCircle()), solvers::io::toJson(closedCubic())});
    in["surfaces"] = json::array({solvers::io::toJson(sphereOctant()), solvers::io::toJson(bicubicPatch())});
    return in;
}

TEST(ExportCli, StepHoldsTheSurfacesExactly)
{
    json in = geometry();
    in["format"] = "step";
    in["path"] = scratchPath("model.step");

    const json out = runOk("export", in);

    EXPECT_EQ(out.value("path", ""), in["path"]);
    ASSERT_TRUE(out.contains("bytes"));
    EXPECT_EQ(out["bytes"].get<std::uintmax_t>(), std::filesystem::file_size(in["path"].get<std::string>()));
    STEPControl_Reader reader;
    ASSERT_EQ(reader.ReadFile(in["path"].get<std::string>().c_str()), IFSelect_RetDone);
    reader.TransferRoots();
    int faces = 0;
    for (TopExp_Explorer e(reader.OneShape(), TopAbs_FACE); e.More(); e.Next(), ++faces) {
        const auto s = Handle(Geom_BSplineSurface)::DownCast(BRep_Tool::Surface(TopoDS::Face(e.Current())));
        ASSERT_FALSE(s.IsNull());
        const Surface3d want = faces == 0 ? sphereOctant() : bicubicPatch();
        for (double u : {0.0, 0.13, 0.5, 0.77, 1.0}) {
            for (double v : {0.0, 0.31, 0.9, 1.0}) {
                const gp_Pnt q = s->Value(u, v);
                EXPECT_LT((Eigen::Vector3d(q.X(), q.Y(), q.Z()) - want.evaluate(u, v)).norm(), kExactRoundTrip);
            }
        }
    }
    EXPECT_EQ(faces, 2);
}

TEST(ExportCli, IgesAndObjAndStlAreWritten)
{
    for (const char* format : {"iges", "obj"}) {
        json in = geometry();
        in["format"] = format;
        in["path"] = scratchPath(std::string("model.") + format);
        const json out = runOk("export", in);
        EXPECT_EQ(out.value("format", ""), format);
        EXPECT_GT(std::filesystem::file_size(in["path"].get<std::string>()), 0u);
    }
    IGESControl_Reader iges;
    ASSERT_EQ(iges.ReadFile(scratchPath("model.iges").c_str()), IFSelect_RetDone);
    EXPECT_EQ(iges.TransferRoots(), 4);  // two curves, two surfaces
    // STL: the curves beside the surfaces are skipped; the count is the tessellations' triangles.
    json in = geometry();
    in["format"] = "stl";
    in["path"] = scratchPath("model.stl");
    const json out = runOk("export", in);
    const size_t triangles = solvers::tessellate(sphereOctant()).triangles.size() + solvers::tessellate(bicubicPatch()).triangles.size();
    EXPECT_EQ(out.value("bytes", 0u), 84 + 50 * triangles);
}

TEST(ExportCli, MeshesGoToStlAndObjOnly)
{
    json in;
    in["meshes"] = json::array({{{"vertices", {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}}, {"triangles", {{0, 1, 2}}}}});
    in["format"] = "stl";
    in["path"] = scratchPath("tri.stl");
    EXPECT_EQ(runOk("export", in).value("bytes", 0), 134);
    in["format"] = "step";
    in["path"] = scratchPath("tri.step");
    const auto r = runCli({"export"}, in.dump());
    EXPECT_EQ(r.status, 2);
    EXPECT_EQ(r.err.rfind("sculptline-cli: meshes: ", 0), 0u) << r.err;
    EXPECT_FALSE(std::filesystem::exists(in["path"].get<std::string>()));
}

struct BadInput {
    const char* name;
    std::function<void(json&)> edit;
    const char* field;  // the message's field, after "sculptline-cli: "
};

TEST(ExportCli, BadInputExitsTwoNamingTheField)
{
    const std::vector<BadInput> cases{
        {"unknown format", [](json& j) { j["format"] = "dxf"; }, "format: "},
        {"format not a string", [](json& j) { j["format"] = 3; }, "format: "},
        {"missing path", [](json& j) { j.erase("path"); }, "path: "},
        {"empty path", [](json& j) { j["path"] = ""; }, "path: "},
        {"unwritable path", [](json& j) { j["path"] = "/nonexistent-sculptline-dir/a.step"; }, "path: "},
        {"directory path", [](json& j) { j["path"] = std::filesystem::temp_directory_path().string(); }, "path: "},
        {"empty input", [](json& j) { j.erase("surfaces"); j["curves"] = json::array(); }, "curves: "},
        {"non-finite point", [](json& j) { j["curves"][0]["points"][1][0] = "nan"; }, "curves[0].points[1][0]: "},
        {"surfaces not an array", [](json& j) { j["surfaces"] = 1; }, "surfaces: "},
        {"bad knots", [](json& j) { j["surfaces"][1]["knotsU"][4] = -1; }, "surfaces[1].knotsU"},
    };
    for (const BadInput& c : cases) {
        SCOPED_TRACE(c.name);
        json in = geometry();
        in["format"] = "step";
        in["path"] = scratchPath("bad.step");
        c.edit(in);
        const auto r = runCli({"export"}, in.dump());
        EXPECT_EQ(r.status, 2);
        EXPECT_EQ(r.err.rfind(std::string("sculptline-cli: ") + c.field, 0), 0u) << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
        EXPECT_TRUE(r.out.empty());
    }
    EXPECT_FALSE(std::filesystem::exists(scratchPath("bad.step")));
}

}  // namespace
}  // namespace sculptline::exchange_test

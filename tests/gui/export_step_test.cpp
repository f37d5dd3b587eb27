// File export under Xvfb: `sculptline data/models/surfaces_drag_start.json --export-step F --quit`
// runs first (tests/gui/CMakeLists.txt, gui_replay_export_step). Given the STEP file the real
// program wrote, When OpenCASCADE reads it back, Then it holds one face per surface of the document
// and one free edge per curve, each the geometry the headless model computes for the same document.
#include "model/document.h"
#include "model/model.h"
#include "model/model_document.h"

#include <BRep_Tool.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Geom_BSplineSurface.hxx>
#include <STEPControl_Reader.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopoDS.hxx>
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>
#include <vector>

namespace {

using namespace sculptline;

/// The window writes the model's exact B-splines with 17 significant digits (solvers/exchange):
/// read back they evaluate as the headless model's to round-off, far inside a nanometre.
constexpr double kExactRoundTrip = 1e-9;

std::string replayDir()
{
    const char* dir = std::getenv("SCULPTLINE_REPLAY_DIR");
    return dir ? dir : "";
}

Eigen::Vector3d eigen(const gp_Pnt& p) { return {p.X(), p.Y(), p.Z()}; }

TEST(ExportStep, TheWindowsStepFileHoldsTheDocumentsSurfacesAndCurves)
{
    // Arrange: the document as the headless model computes it.
    model::Model m;
    model::populateModel(model::loadDocument(SCULPTLINE_DATA_DIR "/models/surfaces_drag_start.json"), m);
    std::vector<solvers::Surface3d> surfaces;
    std::vector<solvers::Curve3d> curves;
    for (const auto& [id, e] : m.entities()) {
        if (e.kind == model::EntityKind::Surface && e.surface) surfaces.push_back(*e.surface);
        if (e.kind == model::EntityKind::Curve && e.world) curves.push_back(*e.world);
    }
    ASSERT_EQ(surfaces.size(), 4u);
    ASSERT_EQ(curves.size(), 7u);

    // Act: read the file the program wrote.
    STEPControl_Reader reader;
    ASSERT_EQ(reader.ReadFile((replayDir() + "/surfaces_drag.step").c_str()), IFSelect_RetDone);
    reader.TransferRoots();
    const TopoDS_Shape shape = reader.OneShape();

    // Assert: one face per surface, in the model's order, the same geometry.
    std::vector<Handle(Geom_BSplineSurface)> faces;
    for (TopExp_Explorer e(shape, TopAbs_FACE); e.More(); e.Next()) {
        faces.push_back(Handle(Geom_BSplineSurface)::DownCast(BRep_Tool::Surface(TopoDS::Face(e.Current()))));
    }
    ASSERT_EQ(faces.size(), surfaces.size());
    for (size_t i = 0; i < faces.size(); ++i) {
        ASSERT_FALSE(faces[i].IsNull()) << "face " << i << " is not a B-spline surface";
        const solvers::Surface3d& s = surfaces[i];
        double worst = 0;
        for (int a = 0; a <= 20; ++a) {
            for (int b = 0; b <= 20; ++b) {
                const double u = s.domainStart(solvers::Direction::U) +
                                 (s.domainEnd(solvers::Direction::U) - s.domainStart(solvers::Direction::U)) * a / 20;
                const double v = s.domainStart(solvers::Direction::V) +
                                 (s.domainEnd(solvers::Direction::V) - s.domainStart(solvers::Direction::V)) * b / 20;
                worst = std::max(worst, (eigen(faces[i]->Value(u, v)) - s.evaluate(u, v)).norm());
            }
        }
        EXPECT_LT(worst, kExactRoundTrip) << "face " << i;
    }
    // Free edges (in no face): the document's curves.
    TopTools_IndexedDataMapOfShapeListOfShape edgeFaces;
    TopExp::MapShapesAndAncestors(shape, TopAbs_EDGE, TopAbs_FACE, edgeFaces);
    std::vector<Handle(Geom_BSplineCurve)> free;
    for (int k = 1; k <= edgeFaces.Extent(); ++k) {
        if (!edgeFaces(k).IsEmpty()) continue;
        double first = 0, last = 0;
        free.push_back(Handle(Geom_BSplineCurve)::DownCast(BRep_Tool::Curve(TopoDS::Edge(edgeFaces.FindKey(k)), first, last)));
    }
    ASSERT_EQ(free.size(), curves.size());
    for (size_t i = 0; i < free.size(); ++i) {
        ASSERT_FALSE(free[i].IsNull()) << "edge " << i << " is not a B-spline curve";
        // Edges may come back in another order: match each curve to the edge nearest to it.
        double best = 1e300;
        for (const auto& c : curves) {
            double worst = 0;
            for (int k = 0; k <= 50; ++k) {
                const double u = c.domainStart() + (c.domainEnd() - c.domainStart()) * k / 50;
                worst = std::max(worst, (eigen(free[i]->Value(u)) - c.evaluate(u)).norm());
            }
            best = std::min(best, worst);
        }
        EXPECT_LT(best, kExactRoundTrip) << "edge " << i;
    }
}

}  // namespace

// STEP and IGES round trips (solvers/exchange/cad_writer.h): Given curves and surfaces with known
// exact geometry, When they are written and read back by OpenCASCADE's own readers
// (STEPControl_Reader, IGESControl_Reader), Then the read geometry is the same B-spline: the same
// degree, knot values and weights, and the same points at many parameters.
#include "solvers/exchange/exchange.h"
#include "tests/exchange/exchange_test_geometry.h"

#include <BRep_Tool.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Geom_RectangularTrimmedSurface.hxx>
#include <Geom_TrimmedCurve.hxx>
#include <IGESControl_Reader.hxx>
#include <STEPControl_Reader.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <set>
#include <unistd.h>

namespace sculptline::exchange_test {
namespace {

namespace ex = solvers::exchange;
using solvers::Direction;

/// The geometry must come back exactly; what may differ is the text's decimal rounding of each
/// number (STEP and IGES write 15-17 significant digits, a relative 1e-15 of coordinates up to
/// 25 mm) and the two evaluators' rounding: far below 1e-9 mm, a nanometre on a millimetre model,
/// which is still a thousand times finer than any modelling tolerance (OCCT's Precision::Confusion
/// is 1e-7). An approximation instead of the exact B-spline would miss it by orders of magnitude.
constexpr double kExactRoundTrip = 1e-9;
constexpr int kSamples = 500;

std::string tempFile(const std::string& name)
{
    const auto dir = std::filesystem::temp_directory_path() / ("sculptline-exchange-test-" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    return (dir / name).string();
}

TopoDS_Shape readBack(ex::Format format, const std::string& path)
{
    if (format == ex::Format::Step) {
        STEPControl_Reader reader;
        EXPECT_EQ(reader.ReadFile(path.c_str()), IFSelect_RetDone);
        reader.TransferRoots();
        return reader.OneShape();
    }
    IGESControl_Reader reader;
    EXPECT_EQ(reader.ReadFile(path.c_str()), IFSelect_RetDone);
    reader.TransferRoots();
    return reader.OneShape();
}

struct ReadCurve {
    Handle(Geom_BSplineCurve) curve;
    double first = 0, last = 0;
};

std::vector<ReadCurve> curvesOf(const TopoDS_Shape& shape)
{
    std::vector<ReadCurve> out;
    for (TopExp_Explorer e(shape, TopAbs_EDGE); e.More(); e.Next()) {
        ReadCurve r;
        Handle(Geom_Curve) c = BRep_Tool::Curve(TopoDS::Edge(e.Current()), r.first, r.last);
        if (auto t = Handle(Geom_TrimmedCurve)::DownCast(c)) c = t->BasisCurve();
        r.curve = Handle(Geom_BSplineCurve)::DownCast(c);
        out.push_back(r);
    }
    return out;
}

std::vector<Handle(Geom_BSplineSurface)> surfacesOf(const TopoDS_Shape& shape)
{
    std::vector<Handle(Geom_BSplineSurface)> out;
    for (TopExp_Explorer e(shape, TopAbs_FACE); e.More(); e.Next()) {
        Handle(Geom_Surface) s = BRep_Tool::Surface(TopoDS::Face(e.Current()));
        if (auto t = Handle(Geom_RectangularTrimmedSurface)::DownCast(s)) s = t->BasisSurface();
        out.push_back(Handle(Geom_BSplineSurface)::DownCast(s));
    }
    return out;
}

Eigen::Vector3d eigen(const gp_Pnt& p) { return {p.X(), p.Y(), p.Z()}; }

// The distinct knot values of the kernel's domain [start, end] (a closed curve's file form repeats
// them outside the domain; an open curve's are all of them when clamped).
std::vector<double> domainKnots(const std::vector<double>& knots, double start, double end)
{
    std::set<double> s;
    for (double k : knots) {
        if (k >= start && k <= end) s.insert(k);
    }
    return {s.begin(), s.end()};
}

std::vector<double> domainKnots(const Handle(Geom_BSplineCurve)& c, double start, double end)
{
    std::vector<double> all;
    for (int i = 1; i <= c->NbKnots(); ++i) all.push_back(c->Knot(i));
    return domainKnots(all, start - kExactRoundTrip, end + kExactRoundTrip);
}

/// Max |C(u) - C'(u)| over kSamples + 1 parameters of the kernel's domain.
double curveDeviation(const Curve3d& c, const Handle(Geom_BSplineCurve)& read)
{
    double worst = 0;
    for (int k = 0; k <= kSamples; ++k) {
        const double u = c.domainStart() + (c.domainEnd() - c.domainStart()) * k / kSamples;
        gp_Pnt q;
        read->D0(u, q);
        worst = std::max(worst, (c.evaluate(u) - eigen(q)).norm());
    }
    return worst;
}

double surfaceDeviation(const Surface3d& s, const Handle(Geom_BSplineSurface)& read)
{
    double worst = 0;
    const int n = 60;
    for (int a = 0; a <= n; ++a) {
        for (int b = 0; b <= n; ++b) {
            const double u = s.domainStart(Direction::U) + (s.domainEnd(Direction::U) - s.domainStart(Direction::U)) * a / n;
            const double v = s.domainStart(Direction::V) + (s.domainEnd(Direction::V) - s.domainStart(Direction::V)) * b / n;
            gp_Pnt q;
            read->D0(u, v, q);
            worst = std::max(worst, (s.evaluate(u, v) - eigen(q)).norm());
        }
    }
    return worst;
}

class CadRoundTrip : public ::testing::TestWithParam<ex::Format> {};

TEST_P(CadRoundTrip, CurvesComeBackExactly)
{
    // Arrange
    ex::ExchangeContent content;
    content.curves = {quarterCircle(), closedCubic(), closedRational(), closedRational({0, 0.5, 2, 1, 1.5}),
                      unclampedCubic()};
    const std::string path = tempFile(std::string("curves.") + ex::formatName(GetParam()));
    // Act
    const auto bytes = ex::writeFile(content, GetParam(), path);
    const std::vector<ReadCurve> read = curvesOf(readBack(GetParam(), path));
    // Assert
    EXPECT_EQ(bytes, std::filesystem::file_size(path));
    ASSERT_EQ(read.size(), content.curves.size());
    for (size_t i = 0; i < read.size(); ++i) {
        SCOPED_TRACE("curve " + std::to_string(i));
        const Curve3d& c = content.curves[i];
        ASSERT_FALSE(read[i].curve.IsNull()) << "not read back as a B-spline";
        EXPECT_EQ(read[i].curve->Degree(), c.degree());
        EXPECT_EQ(read[i].curve->IsRational(), c.isRational());
        EXPECT_NEAR(read[i].first, c.domainStart(), kExactRoundTrip);
        EXPECT_NEAR(read[i].last, c.domainEnd(), kExactRoundTrip);
        const std::vector<double> want = domainKnots(c.knots(), c.domainStart(), c.domainEnd());
        const std::vector<double> got = domainKnots(read[i].curve, c.domainStart(), c.domainEnd());
        ASSERT_EQ(got.size(), want.size());
        for (size_t k = 0; k < want.size(); ++k) EXPECT_NEAR(got[k], want[k], kExactRoundTrip);
        // Clamped open curves come back pole for pole. The others come back as the same geometry
        // in another form: neither format has OCCT's periodic form, and the readers and writers
        // re-form what they see (the STEP reader makes a closed curve periodic again, IGES's
        // GeomToIGES clamps closed and unclamped curves by knot insertion, making new poles and
        // weights); for them the points below are the check.
        const bool clamped = !c.isClosed() && c.knots().front() == c.domainStart() && c.knots().back() == c.domainEnd();
        if (clamped) {
            ASSERT_EQ(read[i].curve->NbPoles(), c.pointCount());
            for (int k = 0; k < c.pointCount(); ++k) {
                EXPECT_NEAR(read[i].curve->Weight(k + 1), c.weight(k), kExactRoundTrip);
                EXPECT_LT((eigen(read[i].curve->Pole(k + 1)) - c.points()[k]).norm(), kExactRoundTrip);
            }
        }
        const double deviation = curveDeviation(c, read[i].curve);
        std::printf("%s curve %zu: max |C - C'| = %.3g mm\n", ex::formatName(GetParam()), i, deviation);
        EXPECT_LT(deviation, kExactRoundTrip);
    }
}

TEST_P(CadRoundTrip, SurfacesComeBackExactly)
{
    ex::ExchangeContent content;
    content.surfaces = {sphereOctant(), bicubicPatch()};
    const std::string path = tempFile(std::string("surfaces.") + ex::formatName(GetParam()));

    ex::writeFile(content, GetParam(), path);
    const std::vector<Handle(Geom_BSplineSurface)> read = surfacesOf(readBack(GetParam(), path));

    ASSERT_EQ(read.size(), content.surfaces.size());
    for (size_t i = 0; i < read.size(); ++i) {
        SCOPED_TRACE("surface " + std::to_string(i));
        const Surface3d& s = content.surfaces[i];
        ASSERT_FALSE(read[i].IsNull()) << "not read back as a B-spline surface";
        EXPECT_EQ(read[i]->UDegree(), s.degreeU());
        EXPECT_EQ(read[i]->VDegree(), s.degreeV());
        ASSERT_EQ(read[i]->NbUPoles(), s.countU());
        ASSERT_EQ(read[i]->NbVPoles(), s.countV());
        for (int a = 0; a < s.countU(); ++a) {
            for (int b = 0; b < s.countV(); ++b) {
                EXPECT_NEAR(read[i]->Weight(a + 1, b + 1), s.weight(a, b), kExactRoundTrip);
                EXPECT_LT((eigen(read[i]->Pole(a + 1, b + 1)) - s.point(a, b)).norm(), kExactRoundTrip);
            }
        }
        std::vector<double> gotU, gotV;
        for (int k = 1; k <= read[i]->NbUKnots(); ++k) gotU.push_back(read[i]->UKnot(k));
        for (int k = 1; k <= read[i]->NbVKnots(); ++k) gotV.push_back(read[i]->VKnot(k));
        const std::vector<double> wantU = domainKnots(s.knotsU(), -1e300, 1e300);
        const std::vector<double> wantV = domainKnots(s.knotsV(), -1e300, 1e300);
        ASSERT_EQ(gotU.size(), wantU.size());
        ASSERT_EQ(gotV.size(), wantV.size());
        for (size_t k = 0; k < wantU.size(); ++k) EXPECT_NEAR(gotU[k], wantU[k], kExactRoundTrip);
        for (size_t k = 0; k < wantV.size(); ++k) EXPECT_NEAR(gotV[k], wantV[k], kExactRoundTrip);
        const double deviation = surfaceDeviation(s, read[i]);
        std::printf("%s surface %zu: max |S - S'| = %.3g mm\n", ex::formatName(GetParam()), i, deviation);
        EXPECT_LT(deviation, kExactRoundTrip);
    }
    // The octant is on the sphere: an independent check that the geometry is the true one.
    for (int a = 0; a <= 20; ++a) {
        for (int b = 0; b <= 20; ++b) {
            EXPECT_NEAR(eigen(read[0]->Value(a / 20.0, b / 20.0)).norm(), 25.0, kExactRoundTrip);
        }
    }
}

INSTANTIATE_TEST_SUITE_P(StepAndIges, CadRoundTrip, ::testing::Values(ex::Format::Step, ex::Format::Iges),
                         [](const auto& info) { return std::string(ex::formatName(info.param)); });

TEST(CadExport, RefusesMeshesAndEmptyContentNamingTheField)
{
    ex::ExchangeContent meshes;
    meshes.meshes.push_back({{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}}});
    for (ex::Format f : {ex::Format::Step, ex::Format::Iges}) {
        try {
            ex::encode(meshes, f);
            ADD_FAILURE() << "meshes accepted by " << ex::formatName(f);
        } catch (const ex::ExchangeError& e) {
            EXPECT_EQ(std::string(e.what()).rfind("meshes: ", 0), 0u) << e.what();
        }
        EXPECT_THROW(ex::encode(ex::ExchangeContent{}, f), ex::ExchangeError);
    }
}

TEST(CadExport, UnwritablePathIsNamedAndLeavesNothingBehind)
{
    ex::ExchangeContent content;
    content.curves = {quarterCircle()};
    try {
        ex::writeFile(content, ex::Format::Step, "/nonexistent-dir/x.step");
        ADD_FAILURE() << "wrote into a missing directory";
    } catch (const ex::ExchangeError& e) {
        EXPECT_EQ(std::string(e.what()).rfind("path: ", 0), 0u) << e.what();
    }
    const std::string dir = tempFile("a-directory");
    std::filesystem::create_directories(dir);
    EXPECT_THROW(ex::writeFile(content, ex::Format::Iges, dir), ex::ExchangeError);
}

}  // namespace
}  // namespace sculptline::exchange_test

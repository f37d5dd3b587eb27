// occt-fit: OpenCASCADE's least-squares B-spline approximation (GeomAPI_PointsToBSpline, cubic, C2)
// of a point list at a sweep of tolerances, for scripts/compare_splprep.py. Test-only: built when
// CMake finds OpenCASCADE (Debian's libocct-*-dev, scripts/debian-packages.txt).
//
//   occt-fit < {"points": [[x,y,z], ..], "tolerances": [t, ..], "repeat": n}
//   -> [{"tolerance": t, "ok": b, "degree": 3, "knots": [flat knot vector], "points": [[x,y,z], ..],
//        "ms": first fit, "ms_min": fastest of n}, ..]
//
// "repeat" (optional, default 1): each tolerance is fitted n times, for timing (the first call in
// the process includes OCCT's own set-up: compare ms_min, the warm figure).
//
// A closed stroke is passed with its first point repeated at the end: PointsToBSpline has no
// periodic mode, so its count for a loop includes the clamped seam.
#include <GeomAPI_PointsToBSpline.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Standard_Failure.hxx>
#include <TColgp_Array1OfPnt.hxx>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <iostream>

int main()
{
    using nlohmann::json;
    json in;
    try {
        in = json::parse(std::cin);
    } catch (const std::exception& e) {
        std::cerr << "occt-fit: input is not JSON: " << e.what() << "\n";
        return 2;
    }
    if (!in.contains("points") || !in["points"].is_array() || in["points"].size() < 2 || !in.contains("tolerances")) {
        std::cerr << "occt-fit: need {\"points\": [[x,y,z], ..] (at least 2), \"tolerances\": [..]}\n";
        return 2;
    }
    const json& pts = in["points"];
    TColgp_Array1OfPnt points(1, static_cast<int>(pts.size()));
    for (size_t i = 0; i < pts.size(); ++i) {
        const json& p = pts[i];
        points.SetValue(static_cast<int>(i) + 1, gp_Pnt(p.at(0).get<double>(), p.at(1).get<double>(), p.size() > 2 ? p.at(2).get<double>() : 0.0));
    }
    const int repeat = in.contains("repeat") ? in["repeat"].get<int>() : 1;
    if (repeat < 1 || repeat > 1000) {
        std::cerr << "occt-fit: repeat must be 1 to 1000\n";
        return 2;
    }
    json out = json::array();
    for (const json& t : in["tolerances"]) {
        const double tol = t.get<double>();
        json r = {{"tolerance", tol}, {"ok", false}};
        try {
            const auto start = std::chrono::steady_clock::now();
            GeomAPI_PointsToBSpline fit(points, 3, 3, GeomAbs_C2, tol);
            const double ms =
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
            double fastest = ms;
            for (int i = 1; i < repeat && fit.IsDone(); ++i) {  // (a failed fit is not timed again)
                const auto again = std::chrono::steady_clock::now();
                GeomAPI_PointsToBSpline warm(points, 3, 3, GeomAbs_C2, tol);
                if (!warm.IsDone()) break;
                fastest = std::min(
                    fastest,
                    std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - again).count());
            }
            if (fit.IsDone()) {
                const Handle(Geom_BSplineCurve) c = fit.Curve();
                json knots = json::array(), poles = json::array();
                for (int i = 1; i <= c->NbKnots(); ++i)
                    for (int m = 0; m < c->Multiplicity(i); ++m) knots.push_back(c->Knot(i));
                for (int i = 1; i <= c->NbPoles(); ++i) {
                    const gp_Pnt& p = c->Pole(i);
                    poles.push_back({p.X(), p.Y(), p.Z()});
                }
                r = {{"tolerance", tol}, {"ok", true}, {"degree", c->Degree()}, {"knots", knots},
                     {"points", poles},  {"ms", ms},   {"ms_min", fastest}};
            }
        } catch (const Standard_Failure& e) {
            r["error"] = e.GetMessageString() ? e.GetMessageString() : "Standard_Failure";
        }
        out.push_back(r);
    }
    std::cout << out.dump() << "\n";
    return 0;
}

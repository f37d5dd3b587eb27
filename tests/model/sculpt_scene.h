#pragma once
// A sculpt over a flat sheet (thesis ch. 6): the fixture of the model's sculpt tests.
#include "model/model.h"

#include <vector>

namespace sculptline::model {

/// A flat bicubic n x n net over [-60, 60]^2 at z = 0 (the base of a sculpt), uniform knots: its
/// domain is [0, n - 3]^2.
inline solvers::Surface3d flatSheet(int n = 7)
{
    solvers::KnotVector knots{0, 0, 0};
    for (int k = 0; k <= n - 3; ++k) knots.push_back(k);
    knots.insert(knots.end(), {double(n - 3), double(n - 3), double(n - 3)});
    std::vector<Eigen::Vector3d> points;
    for (int i = 0; i < n; ++i) {
        for (int j = 0; j < n; ++j) points.emplace_back(-60 + 120.0 * i / (n - 1), -60 + 120.0 * j / (n - 1), 0);
    }
    return solvers::Surface3d(3, 3, knots, knots, n, n, points);
}

/// A base sheet, a vertical plane across it carrying a target arc 12 mm above the sheet, the sculpt.
struct SculptScene {
    Model model;
    EntityId base = 0, plane = 0, target = 0, sculpt = 0;
    explicit SculptScene(double stiffness = 1.0, int netSize = 7)
    {
        base = model.addSurface(flatSheet(netSize));
        plane = model.addPlane(PlaneFrame::fromNormal(Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitY(), 150));
        // An arch across the sheet in the plane y = 0: its ends on the sheet, its middle 12 mm above.
        const PlaneFrame& f = model.find(plane)->frame;
        std::vector<Eigen::Vector3d> local;
        for (int i = 0; i < 5; ++i) {
            const double x = -40 + 20 * i, h = (i == 0 || i == 4) ? 0.0 : 12.0;
            Eigen::Vector3d p = f.toLocal(Eigen::Vector3d(x, 0, h));
            p.z() = 0;
            local.push_back(p);
        }
        target = model.addCurve(plane, solvers::Curve3d(3, {0, 0, 0, 0, 1, 2, 2, 2, 2}, local));
        SurfaceRecipe recipe;
        recipe.mode = Construction::Sculpt;
        recipe.stiffness = stiffness;
        sculpt = model.addSurface({base, target}, recipe);
    }
};

}  // namespace sculptline::model

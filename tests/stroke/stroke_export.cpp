// stroke-export: writes the benchmark strokes (synthesized from known curves with human-like timing
// and noise) as a JSON array [{"name": .., "stroke": K}, ..] on stdout, for
// scripts/compare_splprep.py and for trying `sculptline-cli fit` by hand.
#include "solvers/stroke/stroke_json.h"
#include "solvers/stroke/stroke_synthesis.h"

#include <nlohmann/json.hpp>

#include <iostream>

int main()
{
    using namespace sculptline::solvers::stroke;
    DrawOptions d;
    d.noise = 0.25;  // tablet jitter at the drawing scale (shapes ~100-300 units)
    const std::vector<std::pair<std::string, Stroke>> strokes = {
        {"flourish-200", drawWithSamples(flourishShape(300), 200, d)},
        {"flourish-1000", drawWithSamples(flourishShape(300), 1000, d)},
        {"s-curve", draw(sCurveShape(200), d)},
        {"s-curve-clean", [&] {  // a steady hand on a precise tablet: 0.02 units of noise
             DrawOptions clean = d;
             clean.noise = 0.02;
             return draw(sCurveShape(200), clean);
         }()},
        {"spiral", draw(spiralShape(100, 2.5), d)},
        {"arc", draw(arcShape({0, 0, 0}, 100, 0.2, 2.5), d)},
        {"circle", draw(circleShape({0, 0, 0}, 80), d)},
        {"ellipse", draw(ellipseShape({0, 0, 0}, 120, 60, 0.3), d)},
        {"zigzag", draw(polygonShape({{0, 0, 0}, {60, 80, 0}, {120, 0, 0}, {180, 80, 0}}, false), d)},
        {"square", draw(polygonShape({{0, 0, 0}, {100, 0, 0}, {100, 100, 0}, {0, 100, 0}}, true), d)},
        {"fig43-hairpin", [&] {  // thesis Fig. 4-3's kind of stroke (stroke_fit_test, BM_StrokeFig43)
             DrawOptions slow = d;
             slow.cornerSlowdown = 0.05;
             return drawWithSamples(hairpinShape(200, 3, 25), 600, slow);
         }()},
    };
    nlohmann::json out = nlohmann::json::array();
    for (const auto& [name, s] : strokes) out.push_back({{"name", name}, {"stroke", toJson(s)}});
    std::cout << out.dump() << '\n';
    return 0;
}

// unistroke-report: recognition accuracy on the $1 unistroke logs (tests/data/unistrokes), as
// Markdown confusion matrices for the development subjects (s02-s06) and, with --held-out, for the
// held-out subjects (s07-s11). Usage: unistroke-report [--dev] [--held-out] [--data DIR]
#include "unistroke_eval.h"

#include <cstring>
#include <iomanip>
#include <iostream>

namespace st = sculptline::stroketest;

namespace {

void report(const char* title, const std::vector<st::Recording>& recs)
{
    const st::Confusion c = st::evaluate(recs);
    std::cout << "### " << title << "\n\n" << c.table() << "\nPer class: ";
    for (auto k : {st::ShapeKind::Triangle, st::ShapeKind::Rectangle, st::ShapeKind::Circle, st::ShapeKind::Polyline, st::ShapeKind::Freeform}) {
        std::cout << sculptline::solvers::stroke::shapeName(k) << ' ' << std::fixed << std::setprecision(1) << 100.0 * c.classAccuracy(k) << " %  ";
    }
    std::cout << "\n\n";
}

}  // namespace

int main(int argc, char** argv)
{
    std::string dir = SCULPTLINE_UNISTROKE_DATA;
    bool dev = false, held = false;
    for (int i = 1; i < argc; ++i) {
        if (!std::strcmp(argv[i], "--dev")) dev = true;
        else if (!std::strcmp(argv[i], "--held-out")) held = true;
        else if (!std::strcmp(argv[i], "--data") && i + 1 < argc) dir = argv[++i];
        else {
            std::cerr << "usage: unistroke-report [--dev] [--held-out] [--data DIR]\n";
            return 2;
        }
    }
    if (!dev && !held) dev = true;
    if (dev) report("Development subjects s02-s06 (slow, medium, fast)", st::loadUnistrokes(dir, st::devSubjects()));
    if (held) report("Held-out subjects s07-s11 (slow, medium, fast)", st::loadUnistrokes(dir, st::heldOutSubjects()));
    return 0;
}

// sculptline-cli regularize: a regularized solution of an ill-posed linear system A x = b by truncated
// SVD with a prior, or modified TSVD with a smoothing matrix, at the L-curve's corner or a given k
// (seed 000 §4.2–4.4; solvers/regularization).
//
//   {"matrix": [[..]..] (m rows of n), "rhs": [m] or [[d]..m], "method"?: "tsvd" (default) | "mtsvd",
//    "k"?: truncation (default: the corner), "prior"?: x0 ([n] or [[d]..n], as the solution),
//    "smoothing"?: [[..]..] (p rows of n; mtsvd only; default second differences),
//    "corner_method"?: "knot-removal" | "adaptive-pruning" (default: knot removal for tsvd, pruning for
//    mtsvd; lcurve_corner.h),
//    "svd"?: "default" | "eigen" | "lapack"}
//     -> {"solution": x (the shape of rhs's columns), "k", "corner", "singular_values": [σ1..σr],
//         "rho": [ρ1..ρr], "eta": [η1..ηr], "svd", "corner_method", "elapsed_ms"}
#include "app/cli/cli_support.h"
#include "app/cli/subcommand.h"
#include "solvers/regularization/lcurve_corner.h"
#include "solvers/regularization/mtsvd.h"

#include <optional>
#include <stdexcept>

namespace sculptline::cli {
namespace {

namespace reg = solvers::regularization;

// Size bounds: the SVD costs O(m n²) and the MTSVD sweep O(n² (n + p)); at these bounds one run stays
// within a few seconds on one core (README "Regularization").
constexpr int kMaxRows = 2000;
constexpr int kMaxCols = 1000;
constexpr long kMaxEntries = 1000000;
constexpr int kMaxRhsColumns = 64;
// MTSVD's sweep is O(n² (n + p)): 1000×500 takes about 0.4 s, 1000×1000 5.5 s.
constexpr int kMaxMtsvdCols = 500;

// A matrix of finite numbers, rows × cols; `cols` < 0: any width, taken from the first row.
Eigen::MatrixXd matrixFromJson(const json& j, const std::string& path, int maxRows, int cols, int maxCols)
{
    if (!j.is_array() || j.empty()) throw InputError(path + ": expected a non-empty array of rows");
    if (j.size() > static_cast<size_t>(maxRows)) {
        throw InputError(path + ": " + std::to_string(j.size()) + " rows, at most " + std::to_string(maxRows));
    }
    if (!j[0].is_array()) throw InputError(path + "[0]: expected an array of numbers");
    const size_t width = cols < 0 ? j[0].size() : static_cast<size_t>(cols);
    if (width == 0) throw InputError(path + "[0]: a row must not be empty");
    if (width > static_cast<size_t>(maxCols)) {
        throw InputError(path + "[0]: " + std::to_string(width) + " columns, at most " + std::to_string(maxCols));
    }
    if (static_cast<long>(j.size()) * static_cast<long>(width) > kMaxEntries) {
        throw InputError(path + ": " + std::to_string(j.size()) + "x" + std::to_string(width) + " is more than " +
                         std::to_string(kMaxEntries) + " entries");
    }
    Eigen::MatrixXd m(j.size(), width);
    for (size_t i = 0; i < j.size(); ++i) {
        const std::string row = path + "[" + std::to_string(i) + "]";
        if (!j[i].is_array()) throw InputError(row + ": expected an array of numbers");
        if (j[i].size() != width) {
            throw InputError(row + ": expected " + std::to_string(width) + " numbers, got " + std::to_string(j[i].size()));
        }
        for (size_t c = 0; c < width; ++c) m(i, c) = solvers::io::numberFromJson(j[i][c], row + "[" + std::to_string(c) + "]");
    }
    return m;
}

// [m] (one column) or [[d]..m]; `vector` tells which form was given.
Eigen::MatrixXd columnsFromJson(const json& j, const std::string& path, int rows, bool& vector)
{
    if (!j.is_array() || j.size() != static_cast<size_t>(rows)) {
        throw InputError(path + ": expected " + std::to_string(rows) + " entries (one per " +
                         (path == "rhs" ? "matrix row" : "matrix column") + "), got " +
                         (j.is_array() ? std::to_string(j.size()) : solvers::io::describeValue(j)));
    }
    vector = !j[0].is_array();
    if (vector) {
        Eigen::MatrixXd m(rows, 1);
        for (int i = 0; i < rows; ++i) m(i, 0) = solvers::io::numberFromJson(j[i], path + "[" + std::to_string(i) + "]");
        return m;
    }
    return matrixFromJson(j, path, rows, -1, kMaxRhsColumns);
}

json columnsToJson(const Eigen::MatrixXd& m, bool vector)
{
    json out = json::array();
    for (int i = 0; i < m.rows(); ++i) {
        if (vector) {
            out.push_back(m(i, 0));
        } else {
            json row = json::array();
            for (int c = 0; c < m.cols(); ++c) row.push_back(m(i, c));
            out.push_back(std::move(row));
        }
    }
    return out;
}

std::string stringField(const json& input, const std::string& key, std::initializer_list<const char*> allowed,
                        const std::string& fallback)
{
    if (!input.contains(key)) return fallback;
    const json& v = input[key];
    const std::string s = v.is_string() ? v.get<std::string>() : "";
    std::string list;
    for (const char* a : allowed) {
        if (s == a) return s;
        list += list.empty() ? a : std::string(" or ") + a;
    }
    throw InputError(key + ": expected " + list + ", got " + solvers::io::describeValue(v));
}

json run(const json& input, const Options&)
{
    const Eigen::MatrixXd a = matrixFromJson(field(input, "matrix"), "matrix", kMaxRows, -1, kMaxCols);
    const int n = static_cast<int>(a.cols());
    bool vector = true;
    const Eigen::MatrixXd b = columnsFromJson(field(input, "rhs"), "rhs", static_cast<int>(a.rows()), vector);
    const bool modified = stringField(input, "method", {"tsvd", "mtsvd"}, "tsvd") == "mtsvd";
    Eigen::MatrixXd x0;
    if (input.contains("prior")) {
        bool priorVector = true;
        x0 = columnsFromJson(input["prior"], "prior", n, priorVector);
        if (priorVector != vector || x0.cols() != b.cols()) {
            throw InputError("prior: must have the shape of the solution (" + std::to_string(n) + " entries of " +
                             (vector ? std::string("numbers") : std::to_string(b.cols()) + " numbers each") + ")");
        }
    }
    if (modified && n > kMaxMtsvdCols) {
        throw InputError("matrix: " + std::to_string(n) + " columns, method mtsvd takes at most " +
                         std::to_string(kMaxMtsvdCols));
    }
    Eigen::MatrixXd l;
    if (input.contains("smoothing")) {
        if (!modified) throw InputError("smoothing: only method mtsvd uses a smoothing matrix");
        l = matrixFromJson(input["smoothing"], "smoothing", kMaxRows, n, kMaxCols);
    } else if (modified) {
        if (n < 3) throw InputError("smoothing: the default second differences need at least 3 columns, matrix has " + std::to_string(n));
        l = reg::secondDifferences(n);
    }
    const reg::CornerMethod cornerMethod =
        stringField(input, "corner_method", {"adaptive-pruning", "knot-removal"},
                    reg::cornerMethodName(reg::defaultCornerMethod(modified))) == "knot-removal"
            ? reg::CornerMethod::KnotRemoval
            : reg::CornerMethod::AdaptivePruning;
    const std::string backendName = stringField(input, "svd", {"default", "eigen", "lapack"}, "default");
    if (backendName == "lapack" && !reg::lapackAvailable()) throw InputError("svd: this build has no LAPACKE");
    const reg::SvdBackend backend = backendName == "eigen"    ? reg::SvdBackend::Eigen
                                    : backendName == "lapack" ? reg::SvdBackend::Lapack
                                                              : reg::SvdBackend::Default;
    const json* kJson = input.contains("k") ? &input["k"] : nullptr;
    if (kJson) solvers::io::integerFromJson(*kJson, "k", 1, n);  // type and the loose range, before the work

    const Stopwatch clock;
    const reg::CachedSvd svd(a, backend);
    const int r = svd.rank();
    if (r == 0) throw InputError("matrix: is zero (rank 0); there is nothing to solve");
    const int k = kJson ? solvers::io::integerFromJson(*kJson, "k", 1, r) : 0;
    const reg::ProjectedRhs rhs = reg::projectRhs(svd, b, x0);
    std::optional<reg::MtsvdSolver> mtsvd;
    if (modified) mtsvd.emplace(svd, l);
    const reg::LCurve lc = modified ? mtsvd->lcurve(rhs) : reg::tsvdLCurve(svd, rhs);
    const int corner = reg::lcurveCorner(lc, cornerMethod).k;
    const int used = k > 0 ? k : corner;
    const Eigen::MatrixXd x = modified ? mtsvd->solution(rhs, used) : reg::tsvdSolution(svd, rhs, used);
    const double ms = clock.elapsedMs();

    json out;
    out["solution"] = columnsToJson(x, vector);
    out["k"] = used;
    out["corner"] = corner;
    out["singular_values"] = std::vector<double>(svd.singularValues().data(), svd.singularValues().data() + r);
    out["rho"] = std::vector<double>(lc.rho.data(), lc.rho.data() + r);
    out["eta"] = std::vector<double>(lc.eta.data(), lc.eta.data() + r);
    out["svd"] = reg::svdBackendName(svd.backend());
    out["corner_method"] = reg::cornerMethodName(cornerMethod);
    out["elapsed_ms"] = ms;
    requireFiniteOutput(out);
    return out;
}

json runChecked(const json& input, const Options& options)
{
    try {
        return run(input, options);
    } catch (const std::invalid_argument& e) {  // the solvers' messages start with the input field
        throw InputError(e.what());
    }
}

const SubcommandRegistrar registrar{
    {"regularize",
     "regularized least squares (TSVD/MTSVD at the L-curve corner): {matrix, rhs, method?, k?, prior?, smoothing?} "
     "-> {solution, k, corner, singular_values, rho, eta}",
     &runChecked}};

}  // namespace
}  // namespace sculptline::cli

#include "ui/latency_stats.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

namespace sculptline::ui {
namespace {

double nearestRank(const std::vector<double>& sorted, double percent)
{
    const auto rank = static_cast<size_t>(std::ceil(percent / 100.0 * static_cast<double>(sorted.size())));
    return sorted[std::clamp<size_t>(rank, 1, sorted.size()) - 1];
}

}  // namespace

nlohmann::json LatencyStats::toJson() const
{
    nlohmann::json out = nlohmann::json::object();
    for (const auto& [series, values] : samples_) {
        if (values.empty()) continue;
        std::vector<double> sorted = values;
        std::sort(sorted.begin(), sorted.end());
        out[series] = {{"count", sorted.size()},
                       {"p50_ms", nearestRank(sorted, 50)},
                       {"p99_ms", nearestRank(sorted, 99)},
                       {"max_ms", sorted.back()},
                       {"first_ms", values.front()}};
    }
    return out;
}

bool LatencyStats::write(const std::string& path, const nlohmann::json& extra) const
{
    nlohmann::json out = toJson();
    for (const auto& [key, value] : extra.items()) out[key] = value;
    std::ofstream file(path, std::ios::binary | std::ios::trunc);
    if (file) file << out.dump(2) << "\n";
    return static_cast<bool>(file);
}

}  // namespace sculptline::ui

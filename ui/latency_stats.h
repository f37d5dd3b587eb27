#pragma once
// Latency samples by series ("event", "drag_move", "model_update", ...) and their summary for
// `sculptline --stats` (../shared/interfaces.md): count, p50, p99 and max in milliseconds.
#include <nlohmann/json_fwd.hpp>

#include <map>
#include <string>
#include <vector>

namespace sculptline::ui {

class LatencyStats {
public:
    void add(const std::string& series, double milliseconds) { samples_[series].push_back(milliseconds); }
    /// {"<series>": {"count": n, "p50_ms": .., "p99_ms": .., "max_ms": .., "first_ms": ..}, ...};
    /// percentiles by the nearest-rank method (the smallest sample with at least p % of the samples
    /// at or below it); first_ms is the series' first sample (the cold one: e.g. the session's first
    /// pen-up, whose fitter code and heap no stroke has touched yet).
    nlohmann::json toJson() const;
    /// Writes toJson (plus `extra` members) to `path`; false when the file cannot be written.
    bool write(const std::string& path, const nlohmann::json& extra) const;

private:
    std::map<std::string, std::vector<double>> samples_;
};

}  // namespace sculptline::ui

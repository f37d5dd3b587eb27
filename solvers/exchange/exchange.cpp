#include "solvers/exchange/exchange.h"

#include "solvers/exchange/cad_writer.h"
#include "solvers/exchange/mesh_writer.h"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>

namespace sculptline::solvers::exchange {

std::optional<Format> formatFromName(const std::string& name)
{
    if (name == "step") return Format::Step;
    if (name == "iges") return Format::Iges;
    if (name == "stl") return Format::Stl;
    if (name == "obj") return Format::Obj;
    return std::nullopt;
}

const char* formatName(Format format)
{
    switch (format) {
    case Format::Step: return "step";
    case Format::Iges: return "iges";
    case Format::Stl: return "stl";
    case Format::Obj: return "obj";
    }
    return "?";
}

void checkContent(const ExchangeContent& content, Format format)
{
    if (content.empty()) throw ExchangeError("curves: nothing to export (no curves, surfaces or meshes)");
    const bool cad = format == Format::Step || format == Format::Iges;
    if (cad && !content.meshes.empty()) {
        throw ExchangeError(std::string("meshes: ") + formatName(format) +
                            " carries B-spline curves and surfaces; export meshes as stl or obj");
    }
    if (format == Format::Stl && content.surfaces.empty() && content.meshes.empty()) {
        throw ExchangeError("curves: stl holds triangles only; give surfaces or meshes (or use obj)");
    }
    for (size_t i = 0; i < content.meshes.size(); ++i) {
        const TriangleMesh& m = content.meshes[i];
        const std::string field = "meshes[" + std::to_string(i) + "]";
        for (size_t k = 0; k < m.vertices.size(); ++k) {
            if (!m.vertices[k].allFinite()) {
                throw ExchangeError(field + ".vertices[" + std::to_string(k) + "]: not a finite point");
            }
        }
        for (size_t k = 0; k < m.triangles.size(); ++k) {
            for (int c = 0; c < 3; ++c) {
                const int v = m.triangles[k][c];
                if (v < 0 || static_cast<size_t>(v) >= m.vertices.size()) {
                    throw ExchangeError(field + ".triangles[" + std::to_string(k) + "][" + std::to_string(c) +
                                        "]: index " + std::to_string(v) + " is not one of the " +
                                        std::to_string(m.vertices.size()) + " vertices");
                }
            }
        }
    }
}

std::string encode(const ExchangeContent& content, Format format)
{
    checkContent(content, format);
    switch (format) {
    case Format::Step: return encodeStep(content);
    case Format::Iges: return encodeIges(content);
    case Format::Stl: return encodeStl(content);
    case Format::Obj: return encodeObj(content);
    }
    throw ExchangeError("format: unknown");
}

std::uintmax_t writeFile(const ExchangeContent& content, Format format, const std::string& path)
{
    if (path.empty()) throw ExchangeError("path: empty");
    checkContent(content, format);
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) throw ExchangeError("path: '" + path + "' is a directory");
    // Probe before the work (append mode: nothing is truncated yet), so that a path that cannot be
    // written fails at once, not after a long tessellation; a file the probe created goes again
    // when encoding fails.
    const bool existed = std::filesystem::exists(path, ec);
    {
        std::ofstream probe(path, std::ios::binary | std::ios::app);
        if (!probe) throw ExchangeError("path: cannot write '" + path + "' (" + std::strerror(errno) + ")");
    }
    std::string bytes;
    try {
        bytes = encode(content, format);
    } catch (...) {
        if (!existed) std::filesystem::remove(path, ec);
        throw;
    }
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    out.close();
    if (!out) throw ExchangeError("path: writing '" + path + "' failed (" + std::strerror(errno) + ")");
    return bytes.size();
}

}  // namespace sculptline::solvers::exchange

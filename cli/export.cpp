#include "cli/export.hpp"

#include <filesystem>
#include <type_traits>

#include "cli/batch.hpp"
#include "lac/common/error.hpp"
#include "lac/export/export_curve.hpp"
#include "lac/export/export_space_curve.hpp"

namespace lac::cli {

namespace {

/// In batch mode FILE gets _row<N> before its extension (out/c.step → out/c_row3.step).
std::string row_path(const std::string& path, long row) {
  if (row <= 0) return path;
  const size_t dot = path.find_last_of('.'), slash = path.find_last_of('/');
  const size_t at = dot == std::string::npos || (slash != std::string::npos && dot < slash) ? path.size() : dot;
  return path.substr(0, at) + "_row" + std::to_string(row) + path.substr(at);
}

/// A writer's InputError ("write_file: export: …") as the command's ("lac: export: …").
template <class F>
auto as_export_error(F&& f) {
  try {
    return f();
  } catch (const InputError& e) {
    const std::string what = e.what(), key = ": export: ";
    const size_t at = what.find(key);
    throw_input_error("lac", "export", at == std::string::npos ? what : what.substr(at + key.size()));
  }
}

/// The "export" block of a planar or space export (space: the curvature check does not apply, null).
template <class R>
Json export_block(const R& r, const std::string& path, ExportFormat format) {
  constexpr bool planar = std::is_same_v<R, ExportResult>;
  const auto planar_only = [&](auto value) { return planar && r.usable() ? Json(value) : Json(nullptr); };
  bool monotone = false;
  long monotone_segments = 0, constant_segments = 0;
  double jump = 0;
  if constexpr (planar) {
    monotone = r.info.curvature_monotone;
    monotone_segments = r.info.monotone_segments;
    constant_segments = r.info.constant_curvature_segments;
    jump = r.info.max_curvature_jump;
  }
  return {{"file", r.usable() ? Json(path) : Json(nullptr)},
          {"format", to_string(format)},
          {"degree", r.usable() ? Json(r.curve.degree) : Json(nullptr)},
          {"control_points", r.usable() ? Json(r.curve.control_points.size()) : Json(nullptr)},
          {"max_deviation", number(r.info.max_deviation)},
          {"curvature_monotone", planar_only(monotone)},
          {"tolerance", number(r.info.tolerance)},
          {"spans", r.info.spans},
          {"continuity", r.info.continuity},
          {"monotone_segments", planar ? Json(monotone_segments) : Json(nullptr)},
          {"constant_curvature_segments", planar ? Json(constant_segments) : Json(nullptr)},
          {"max_curvature_jump", planar ? number(jump) : Json(nullptr)},
          {"status", std::string(to_string(r.summary.status))},
          {"message", r.summary.message.empty() ? Json(nullptr) : Json(r.summary.message)}};
}

/// --export for one curve: `prepare` checks the request (prepare_export or prepare_space_export),
/// `run` makes and writes the B-spline (export_curve) when there is a curve (`have`).
template <class Prepare, class Run>
void add_export_with(Json& report, bool have, const CommonArgs& common, Prepare&& prepare, Run&& run) {
  const std::string file = export_file(common);
  if (file.empty()) return;
  if (common.export_tol && !(*common.export_tol > 0 && std::isfinite(*common.export_tol)))
    throw_input_error("lac", "export-tol", *common.export_tol, "(0, inf)");
  const PreparedExport prepared = prepare(ExportRequest{.path = file,
                                                        .tolerance = common.export_tol.value_or(0.0),
                                                        .degree = common.export_degree,
                                                        .comb = common.comb,
                                                        .fit_max_degree = common.export_fit_degree},
                                          ExportNames{"lac", "export", "export-tol", "export-degree", "export-fit-degree"});
  if (!have) {
    report["export"] = nullptr;
    return;
  }
  const std::string path = row_path(file, current_batch_row());
  if (common.export_path.back() == '/') {
    std::error_code ec;
    std::filesystem::create_directories(common.export_path, ec);
    if (ec) throw_input_error("lac", "export", "cannot create the folder '" + common.export_path + "': " + ec.message());
  }
  const auto r = as_export_error([&] { return run(path, prepared); });
  record_status(r.summary.status);
  report["export"] = export_block(r, path, prepared.format);
}

}  // namespace

void add_export(Json& report, const PlanarCurve* curve, const CommonArgs& common) {
  add_export_with(report, curve != nullptr, common, prepare_export,
                  [&](const std::string& path, const PreparedExport& p) { return export_curve(*curve, path, p); });
}

void add_export(Json& report, const QuadraticArc* arc, const CommonArgs& common) {
  add_export_with(report, arc != nullptr, common, prepare_export, [&](const std::string& path, const PreparedExport& p) {
    return export_curve(arc->curve, arc->s0, arc->s1, path, p);
  });
}

void add_export(Json& report, const SpaceCurve* curve, const CommonArgs& common) {
  add_export_with(report, curve != nullptr, common, prepare_space_export,
                  [&](const std::string& path, const PreparedExport& p) { return export_curve(*curve, path, p); });
}

}  // namespace lac::cli

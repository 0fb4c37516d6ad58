// The common keys of every report and print_report (cli/report.hpp).
#include "cli/report.hpp"

#include <cmath>
#include <iostream>

#include "cli/command.hpp"

namespace lac::cli {

Json number(double v) { return std::isfinite(v) ? Json(v) : Json(nullptr); }
Json number(const std::optional<double>& v) { return v ? number(*v) : Json(nullptr); }
Json xy(std::complex<double> p) { return Json{{"x", number(p.real())}, {"y", number(p.imag())}}; }
Json xyz(const Vec3& p) { return Json{{"x", number(p.x())}, {"y", number(p.y())}, {"z", number(p.z())}}; }

namespace {

Json text_or_null(const std::string& s) { return s.empty() ? Json(nullptr) : Json(s); }

Json common_keys(Status status, const std::string& message, const Json& iterations, long evaluations, double seconds,
                 const std::string& solver, const std::string& integrator, const Residuals& residuals,
                 const std::optional<double>& error, double accept) {
  record_status(status);
  Json j;
  j["status"] = std::string(to_string(status));
  j["message"] = text_or_null(message);
  j["length"] = nullptr;
  j["kappa0"] = nullptr;
  j["kappa1"] = nullptr;
  j["iterations"] = iterations;
  j["evaluations"] = evaluations;
  j["seconds"] = seconds;
  j["solver"] = text_or_null(solver);
  j["integrator"] = text_or_null(integrator);
  j["residuals"] = {{"position", number(residuals.position)},
                    {"angle", number(residuals.angle)},
                    {"curvature", number(residuals.curvature)}};
  j["error"] = number(error);
  j["accept"] = accept;
  j["segments"] = Json::array();
  return j;
}

}  // namespace

Json construction_report(const Summary& s) {
  return common_keys(s.status, s.message, s.iterations, s.evaluations, s.seconds, s.solver, s.integrator, s.residuals,
                     s.error, s.accept);
}

Json evaluation_report(Status status, const std::string& message, long evaluations, double seconds,
                       const std::string& integrator, std::optional<double> error, double accept) {
  return common_keys(status, message, nullptr, evaluations, seconds, "", integrator, {}, error, accept);
}

void print_report(const Report& report, const std::string& format, bool comb) {
  if (format == "csv") {
    write_csv_report(std::cout, report.json);
  } else if (format == "svg") {
    write_svg(std::cout, report, comb);
  } else {
    std::cout << report.json.dump(2) << "\n";
  }
}

}  // namespace lac::cli

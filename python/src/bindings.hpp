#pragma once
// Shared pieces of the Python module `lac._lac` (python/): the result and curve classes handed to
// Python, keyword options read through one small table per construction, and the column objects
// (lac.Columns) that evaluations return.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <complex>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "lac/common/error.hpp"
#include "lac/common/summary.hpp"
#include "lac/constructions/g1_hermite.hpp"
#include "lac/constructions/g2_hermite.hpp"
#include "lac/constructions/triangle_g1.hpp"
#include "lac/curves/planar/planar_curve.hpp"
#include "lac/curves/space/space_curve.hpp"
#include "lac/integrators/registry.hpp"

namespace lacpy {

namespace py = pybind11;

/// A planar curve and the quadrature method its positions are integrated with.
struct Curve {
  lac::PlanarCurve curve;
  lac::AnyQuadrature integrator = lac::GaussLegendre{};
};

/// A space curve (its ODE settings are its own).
struct SpaceCurve {
  lac::SpaceCurve curve;
};

/// What every construction returns to Python: the summary, the curve (None unless usable) and the
/// construction's own details as a dict.
struct Result {
  lac::Summary summary;
  py::object curve = py::none();
  py::dict info;
};

/// summary as a dict with the CLI's report keys (docs/cli.md "Schema"); length/kappa0/kappa1 from
/// `curve` when there is one.
py::dict summary_dict(const Result& r);

/// One keyword option of a construction: its name, how it is applied to the options struct `O`,
/// and its help text (docstrings). The tables live in constructions.cpp, one per construction.
template <class O>
struct OptionRow {
  const char* name;
  std::function<void(O&, py::handle)> apply;
  const char* help;
};

/// Applies the keyword arguments `kw` through `table`; TypeError for a keyword the table does not
/// have (naming the closest valid one), lac::InputError from the conversions and the options'
/// validation. Keywords in `skip` are left to the caller.
template <class O>
void apply_options(O& options, const py::dict& kw, const std::vector<OptionRow<O>>& table, const char* function,
                   std::initializer_list<const char*> skip = {});

/// The closest of `names` to `name` (edit distance), for "did you mean" messages.
std::string closest(const std::string& name, const std::vector<std::string>& names);
[[noreturn]] void unknown_keyword(const char* function, const std::string& name, const std::vector<std::string>& valid);

/// The quadrature keywords shared by every planar construction, as the CLI's --integrator, --h,
/// --tol, --panels: `integrator` ("auto" or a registry name), its options. Removed from `kw`.
struct QuadratureArgs {
  std::string integrator;
  lac::QuadratureOptions options;
  bool any_option() const { return options.h || options.tol || options.panels; }
  /// make_quadrature(integrator, options); InputError "integrator" when options are given with "auto".
  std::optional<lac::AnyQuadrature> method(const char* function) const;
};
QuadratureArgs take_quadrature(py::dict& kw, const char* default_integrator);

/// A point (x, y) from a tuple, list, complex or numpy array; InputError naming `name` otherwise.
std::complex<double> point2(py::handle h, const char* function, const char* name);
lac::Vec3 point3(py::handle h, const char* function, const char* name);
double real(py::handle h, const char* function, const char* name);

/// A lac.Columns (attribute and key access) from named arrays.
py::object columns(py::dict data);

/// "ok" … "inaccurate"
inline std::string status_text(lac::Status s) { return std::string(lac::to_string(s)); }

/// The options of a construction from keyword arguments (tables in constructions.cpp; shared with
/// solve_batch). `kw` may also hold the quadrature keywords.
lac::G1HermiteOptions g1_options(py::dict kw, const char* function);
lac::G2Options g2_options(py::dict kw, const char* function);
lac::TriangleOptions triangle_options(py::dict kw, const char* function);

void bind_curves(py::module_& m);
void bind_constructions(py::module_& m);
void bind_batch(py::module_& m);
void bind_special(py::module_& m);
void bind_geometry(py::module_& m);  // geometry.cpp
void bind_export(py::module_& m);    // export.cpp

// ---- template definitions ----

template <class O>
void apply_options(O& options, const py::dict& kw, const std::vector<OptionRow<O>>& table, const char* function,
                   std::initializer_list<const char*> skip) {
  for (auto item : kw) {
    const std::string key = py::str(item.first);
    bool skipped = false;
    for (const char* s : skip) skipped = skipped || key == s;
    if (skipped) continue;
    const OptionRow<O>* row = nullptr;
    for (const OptionRow<O>& r : table)
      if (key == r.name) row = &r;
    if (!row) {
      std::vector<std::string> valid;
      for (const OptionRow<O>& r : table) valid.emplace_back(r.name);
      for (const char* s : skip) valid.emplace_back(s);
      unknown_keyword(function, key, valid);
    }
    try {
      row->apply(options, item.second);
    } catch (const py::cast_error&) {
      lac::throw_input_error(function, key, "cannot be converted from " + std::string(py::str(py::type::of(item.second))));
    }
  }
}

}  // namespace lacpy

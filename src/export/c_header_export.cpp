#include "src/export/c_header_export.hpp"

#include <array>
#include <cctype>
#include <cmath>
#include <limits>
#include <set>

#include "src/core/error.hpp"
#include "src/core/escape.hpp"
#include "src/core/numbers.hpp"
#include "src/core/version.hpp"

namespace hydrocoef {

namespace {

bool is_cubic(Interpolation method) {
  return method == Interpolation::Pchip || method == Interpolation::Akima || method == Interpolation::NaturalSpline;
}

bool valid_identifier(std::string_view text) {
  if (text.empty() || std::isdigit(static_cast<unsigned char>(text.front()))) return false;
  for (char c : text)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_')) return false;
  return true;
}

std::string upper(std::string text) {
  for (char& c : text) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return text;
}

// Text safe inside a C block comment (src/core/escape.hpp).
std::string comment_safe(std::string_view text) { return escape::c_comment(text); }

// A C literal of the value: shortest round-trip double, or (single precision)
// the value rounded to float written as its shortest round-trip float with an
// 'f' suffix.
class LiteralWriter {
 public:
  LiteralWriter(bool single, std::string what) : single_(single), what_(std::move(what)) {}

  std::string operator()(double value) const {
    if (!single_) return shortest_number(value);
    if (std::abs(value) > static_cast<double>(std::numeric_limits<float>::max())) {
      throw InputError("format c --float: " + what_ + " value " + shortest_number(value) +
                       " does not fit in a float; expected |value| <= 3.4e38 (export in double precision)");
    }
    std::string text = shortest_float(static_cast<float>(value));
    if (text.find_first_of(".e") == std::string::npos) text += ".0";
    return text + "f";
  }

 private:
  bool single_;
  std::string what_;
};

void append_array(std::string& out, const std::vector<double>& values, const LiteralWriter& literal,
                  std::size_t per_line) {
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (i % per_line == 0) out += "\n  ";
    out += literal(values[i]);
    if (i + 1 < values.size()) out += ", ";
  }
  out += "\n";
}

// The evaluation function. @P@ is the identifier, @R@ the real type, @F@ the
// literal suffix. It mirrors GridTable::locate and the local sum
// statement by statement (see grid_table.cpp); keep them in step.
constexpr const char* kEvaluation = R"C(
/* Evaluates every output at x (one coordinate per axis, axis order and
 * units). Returns 0 and fills out[0 .. @P@_N_OUTPUTS-1]; or returns a + 1,
 * leaving out untouched, when coordinate a is NaN or infinite, or outside its
 * range on an axis whose policy is "error". */
static inline int @P@_eval(const @R@ x[@P@_N_AXES], @R@ out[@P@_N_OUTPUTS])
{
  @R@ w[@P@_N_AXES][4];
  @R@ inner[@P@_N_INNER];
  const @R@* data;
  const @R@* last;
  unsigned long base = 0;
  unsigned long length = 1;
  unsigned long j;
  unsigned long t;
  int a;
  int e;
  int k;
  for (a = 0; a < @P@_N_AXES; ++a) {
    const @R@* bp = @P@_breakpoints[a];
    const unsigned long count = @P@_breakpoint_count[a];
    const unsigned long stride = @P@_node_stride[a];
    const @R@ v = x[a];
    unsigned long cell = 0;
    @R@ h;
    @R@ s;
    if (v >= bp[0] && v <= bp[count - 1]) {
      /* The cell: the last breakpoint <= v among bp[0 .. count-2]. */
      const @R@* first = bp;
      unsigned long span = count - 1;
      while (span > 1) {
        const unsigned long half = span / 2;
        first = first[half] <= v ? first + half : first;
        span -= half;
      }
      cell = (unsigned long)(first - bp);
    } else {
      const int below = v < bp[0];
      int policy = @P@_policy[a];
      if (!isfinite(v) || policy == @P@_POLICY_ERROR) return a + 1;
      cell = below ? 0 : count - 2;
      if (@P@_K == 1) policy = @P@_POLICY_CLAMP;
      if (@P@_K == 2 && policy == @P@_POLICY_LINEAR) policy = @P@_POLICY_METHOD;
      if (policy == @P@_POLICY_CLAMP) {
        /* The end node's value alone; flat along this axis. */
        const int end = (below || @P@_K == 1) ? 0 : (@P@_K == 4 ? 2 : 1);
        base += ((@P@_K == 1 && !below) ? cell + 1 : cell) * stride;
        for (e = 0; e < @P@_K; ++e) w[a][e] = e == end ? 1.0@F@ : 0.0@F@;
        continue;
      }
      if (@P@_K == 4 && policy == @P@_POLICY_LINEAR) {
        /* End value plus end slope times the distance beyond the end. */
        const @R@ distance = v - (below ? bp[0] : bp[count - 1]);
        const int end = below ? 0 : 2;
        base += cell * stride;
        for (e = 0; e < 4; ++e) w[a][e] = e == end ? 1.0@F@ : (e == end + 1 ? distance : 0.0@F@);
        continue;
      }
      /* Policy "method": the end cell's polynomial at s outside [0, 1]. */
    }
    h = bp[cell + 1] - bp[cell];
    s = (v - bp[cell]) / h;
    if (@P@_K == 1) {
      /* Nearest: a tie (s = 0.5) goes to the upper breakpoint. */
      base += (s >= 0.5@F@ ? cell + 1 : cell) * stride;
      w[a][0] = 1.0@F@;
    } else if (@P@_K == 2) {
      base += cell * stride;
      w[a][0] = 1.0@F@ - s;
      w[a][1] = s;
    } else {
      /* Cubic Hermite basis: corner 0 value, corner 0 slope, corner 1 value,
       * corner 1 slope; slope terms carry h (slopes are per axis unit). */
      const @R@ s2 = s * s;
      const @R@ s3 = s2 * s;
      base += cell * stride;
      w[a][0] = 2.0@F@ * s3 - 3.0@F@ * s2 + 1.0@F@;
      w[a][1] = h * (s3 - 2.0@F@ * s2 + s);
      w[a][2] = 3.0@F@ * s2 - 2.0@F@ * s3;
      w[a][3] = h * (s3 - s2);
    }
  }
  /* The tensor-product sum over the cell's @P@_N_TERMS terms: the weights of
   * axes 0 .. n-2 multiplied out, the last axis's weights applied to partial sums. */
  data = @P@_table + base * @P@_NODE_BLOCK;
  inner[0] = 1.0@F@;
  for (a = 0; a + 1 < @P@_N_AXES; ++a) {
    for (e = @P@_K - 1; e >= 1; --e) {
      for (j = 0; j < length; ++j) inner[(unsigned long)e * length + j] = inner[j] * w[a][e];
    }
    for (j = 0; j < length; ++j) inner[j] *= w[a][0];
    length *= @P@_K;
  }
  last = w[@P@_N_AXES - 1];
  for (k = 0; k < @P@_N_OUTPUTS; ++k) {
    @R@ total = 0.0@F@;
    for (e = 0; e < @P@_K; ++e) {
      const unsigned long* offsets = @P@_term_offsets + (unsigned long)e * @P@_N_INNER;
      @R@ part = 0.0@F@;
      for (t = 0; t < @P@_N_INNER; ++t) part += inner[t] * data[offsets[t] + (unsigned long)k];
      total += last[e] * part;
    }
    out[k] = total;
  }
  return 0;
}
)C";

std::string replace_all(std::string text, std::string_view from, std::string_view to) {
  for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
    text.replace(at, from.size(), to);
  return text;
}

}  // namespace

std::string c_identifier_from(std::string_view name) {
  std::string out = "hc_";
  for (char c : name) {
    const auto u = static_cast<unsigned char>(c);
    out += std::isalnum(u) && u < 128 ? static_cast<char>(std::tolower(u)) : '_';
  }
  return out;
}

std::string c_header_text(const GridTable& table, const ExportMetadata& metadata, const CHeaderOptions& options) {
  check_metadata(table, metadata);
  const std::string p = options.identifier.empty() ? c_identifier_from(metadata.surface_name) : options.identifier;
  if (!valid_identifier(p)) {
    throw InputError("format c: identifier '" + p + "' is not a C identifier; expected letters, digits and '_', " +
                     "not starting with a digit");
  }
  const bool single = options.single_precision;
  const std::string real = single ? "float" : "double";
  const std::size_t n = table.axis_count();
  const std::size_t n_out = table.output_count();
  const bool cubic = is_cubic(table.method());
  const std::size_t k_terms = table.method() == Interpolation::Nearest ? 1 : (cubic ? 4 : 2);
  const std::size_t node_block = cubic ? (std::size_t{1} << n) * n_out : n_out;
  std::size_t n_inner = 1;
  for (std::size_t a = 0; a + 1 < n; ++a) n_inner *= k_terms;
  const std::size_t n_terms = n_inner * k_terms;

  // The term offsets, as GridTable computes them.
  std::vector<std::size_t> strides(n);
  std::size_t nodes = 1;
  for (std::size_t a = 0; a < n; ++a) {
    strides[a] = nodes;
    nodes *= table.axes()[a].breakpoints.size();
  }
  std::vector<std::size_t> term_offsets(n_terms, 0);
  for (std::size_t t = 0; t < n_terms; ++t) {
    std::size_t rest = t;
    for (std::size_t a = 0; a < n; ++a) {
      const std::size_t e = rest % k_terms;
      rest /= k_terms;
      const std::size_t next_node = strides[a] * node_block;
      const std::size_t slope = cubic ? (std::size_t{1} << a) * n_out : 0;
      const std::array<std::size_t, 4> axis_offsets =
          cubic ? std::array<std::size_t, 4>{0, slope, next_node, next_node + slope}
                : std::array<std::size_t, 4>{0, next_node, 0, 0};
      term_offsets[t] += axis_offsets[e];
    }
  }

  std::string h;
  const std::string guard = upper(p) + "_H_INCLUDED";
  h += "/* " + p + ".h: a hydrocoef coefficient table as self-contained C99 (also valid C++).\n";
  h += " *\n * Generated by hydrocoef " + std::string(kVersion) + " from " + comment_safe(provenance_line(metadata)) +
       ".\n";
  h += " * Outputs in sign convention " + sign_convention_text(metadata.sign_convention) + ".\n";
  h += " * Body axes x forward, y starboard, z down (SNAME); SI units.\n *\n";
  h += " * Interpolation: " + std::string(interpolation_name(table.method())) +
       (cubic ? " (tensor-product cubic Hermite; the table holds per node the value and every mixed derivative)"
              : (k_terms == 2 ? " (multilinear in each cell)" : " (value of the nearest node; a tie goes up)")) +
       "; " + real + " precision.\n";
  h += " * Axes (x[] order), valid range and out-of-range policy:\n";
  for (std::size_t a = 0; a < n; ++a) {
    const GridAxis& axis = table.axes()[a];
    h += " *   x[" + std::to_string(a) + "] " + comment_safe(axis.name) + " [" + comment_safe(metadata.axis_units[a]) +
         "]: " + std::to_string(axis.breakpoints.size()) + " breakpoints in [" +
         shortest_number(axis.breakpoints.front()) + ", " + shortest_number(axis.breakpoints.back()) +
         "], outside: " + std::string(extrapolation_name(axis.extrapolation)) + "\n";
  }
  h += " * Outputs (out[] order):\n";
  for (std::size_t k = 0; k < n_out; ++k)
    h += " *   out[" + std::to_string(k) + "] " + comment_safe(table.outputs()[k]) + " [" +
         comment_safe(metadata.output_units[k]) + "]\n";
  if (!metadata.far_from_data.empty()) {
    // A controller engineer must see which entries are extrapolation, not data.
    h += " * Far from every CFD run (the RBF was extrapolated there, not fitted to data): " +
         std::to_string(metadata.far_from_data.size()) + " nodes:\n";
    for (const auto& point : metadata.far_from_data) {
      std::string text;
      for (std::size_t a = 0; a < point.size(); ++a)
        text += (a ? ", " : "") + comment_safe(table.axes()[a].name) + " = " + shortest_number(point[a]);
      h += " *   (" + text + ")\n";
    }
  }
  h += " * Policies: error = the call fails (returns axis + 1); clamp = the end value; linear = end value plus\n"
       " * the end slope times the distance (nearest: as clamp); method = the end cell's own polynomial.\n *\n";
  h += " * Table layout: node (i_0, ..., i_{n-1}), i_a the breakpoint index on axis a, axis 0 fastest:\n"
       " *   node = ((i_{n-1} * n_{n-2} + ... + i_2) * n_1 + i_1) * n_0 + i_0 = sum_a i_a * " +
       p + "_node_stride[a]\n";
  if (cubic) {
    h += " *   " + p + "_table[(node * 2^n + S) * " + p +
         "_N_OUTPUTS + k]: output k's mixed derivative over the axis set S\n"
         " *   (bit a of S set: one derivative along axis a, in output unit per axis unit; S = 0: the value).\n";
  } else {
    h += " *   " + p + "_table[node * " + p + "_N_OUTPUTS + k]: output k's value at the node.\n";
  }
  h += " *\n * Usage:\n *   " + real + " x[" + p + "_N_AXES] = {...}, out[" + p + "_N_OUTPUTS];\n *   if (" + p +
       "_eval(x, out) != 0) { outside an \"error\" axis, or not finite }\n */\n";
  h += "#ifndef " + guard + "\n#define " + guard + "\n\n#include <math.h>\n\n";
  h += "typedef " + real + " " + p + "_real;\n\n";
  h += "#define " + p + "_N_AXES " + std::to_string(n) + "\n";
  h += "#define " + p + "_N_OUTPUTS " + std::to_string(n_out) + "\n";
  // Index macros by name, when the names make distinct identifiers.
  auto name_macros = [&](const std::string& kind, const std::vector<std::string>& names) {
    std::set<std::string> seen;
    std::string text;
    for (std::size_t i = 0; i < names.size(); ++i) {
      const std::string macro = p + "_" + kind + "_" + upper(c_identifier_from(names[i]).substr(3));
      if (!seen.insert(macro).second) return std::string();
      text += "#define " + macro + " " + std::to_string(i) + "\n";
    }
    return text;
  };
  std::vector<std::string> axis_names;
  for (const GridAxis& axis : table.axes()) axis_names.push_back(axis.name);
  h += name_macros("AXIS", axis_names);
  h += name_macros("OUT", table.outputs());
  h += "\n/* Out-of-range policies. */\n";
  h += "#define " + p + "_POLICY_ERROR 0\n#define " + p + "_POLICY_CLAMP 1\n#define " + p +
       "_POLICY_LINEAR 2\n#define " + p + "_POLICY_METHOD 3\n\n";
  h += "/* Terms per axis in a cell (1 nearest, 2 linear, 4 cubic Hermite), terms per cell, numbers per node. */\n";
  h += "#define " + p + "_K " + std::to_string(k_terms) + "\n";
  h += "#define " + p + "_N_INNER " + std::to_string(n_inner) + "UL\n";
  h += "#define " + p + "_N_TERMS " + std::to_string(n_terms) + "UL\n";
  h += "#define " + p + "_NODE_BLOCK " + std::to_string(node_block) + "UL\n\n";

  for (std::size_t a = 0; a < n; ++a) {
    const GridAxis& axis = table.axes()[a];
    h += "/* axis " + std::to_string(a) + ": " + comment_safe(axis.name) + " [" + comment_safe(metadata.axis_units[a]) +
         "] */\nstatic const " + real + " " + p + "_bp_" + std::to_string(a) + "[" +
         std::to_string(axis.breakpoints.size()) + "] = {";
    append_array(h, axis.breakpoints, LiteralWriter(single, "breakpoint of axis '" + axis.name + "'"), 6);
    h += "};\n";
  }
  h += "static const " + real + "* const " + p + "_breakpoints[" + p + "_N_AXES] = {";
  for (std::size_t a = 0; a < n; ++a) h += (a ? ", " : "") + p + "_bp_" + std::to_string(a);
  h += "};\nstatic const unsigned long " + p + "_breakpoint_count[" + p + "_N_AXES] = {";
  for (std::size_t a = 0; a < n; ++a) h += (a ? ", " : "") + std::to_string(table.axes()[a].breakpoints.size()) + "UL";
  h += "};\nstatic const unsigned long " + p + "_node_stride[" + p + "_N_AXES] = {";
  for (std::size_t a = 0; a < n; ++a) h += (a ? ", " : "") + std::to_string(strides[a]) + "UL";
  h += "};\nstatic const int " + p + "_policy[" + p + "_N_AXES] = {";
  for (std::size_t a = 0; a < n; ++a) {
    h += a ? ", " : "";
    switch (table.axes()[a].extrapolation) {
      case Extrapolation::Error: h += p + "_POLICY_ERROR"; break;
      case Extrapolation::Clamp: h += p + "_POLICY_CLAMP"; break;
      case Extrapolation::Linear: h += p + "_POLICY_LINEAR"; break;
      case Extrapolation::Method: h += p + "_POLICY_METHOD"; break;
    }
  }
  h += "};\n\n/* Offset of each term of a cell's sum from the cell's first number, axis 0's term fastest. */\n";
  h += "static const unsigned long " + p + "_term_offsets[" + p + "_N_TERMS] = {";
  for (std::size_t t = 0; t < n_terms; ++t) {
    if (t % 12 == 0) h += "\n  ";
    h += std::to_string(term_offsets[t]) + "UL" + (t + 1 < n_terms ? ", " : "");
  }
  h += "\n};\n\n";
  const std::vector<double>& data = cubic ? table.hermite_data() : table.values();
  h += "/* " + std::to_string(table.node_count()) + " nodes x " + std::to_string(node_block) +
       " numbers, laid out as described at the top. */\n";
  h += "static const " + real + " " + p + "_table[" + std::to_string(data.size()) + "] = {";
  append_array(h, data, LiteralWriter(single, "table"), 4);
  h += "};\n";
  h += replace_all(replace_all(replace_all(kEvaluation, "@P@", p), "@R@", real), "@F@", single ? "f" : "");
  h += "\n#endif /* " + guard + " */\n";
  return h;
}

}  // namespace hydrocoef

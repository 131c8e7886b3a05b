// src/commands/batch.cpp -- see batch.hpp.
#include "commands/batch.hpp"

#include <cmath>
#include <exception>
#include <new>
#include <string>

#include <sepax/error.hpp>

#include "commands/query_output.hpp"

namespace sepax::cli {

namespace {

struct LineError {
  std::string message;
};

io::ShapeData points_from_json(const json::Value* v, const char* key) {
  const std::string k = key;
  if (!v) throw LineError{"missing key \"" + k + "\""};
  if (!v->is_array()) throw LineError{k + ": expected an array of points [[x,y,z], ...], got " + kind_name(*v)};
  io::ShapeData s;
  s.kind = io::ShapeData::Kind::Points;
  s.name = k;
  const auto& arr = v->as_array();
  if (arr.empty()) throw LineError{k + ": no points"};
  for (std::size_t i = 0; i < arr.size(); ++i) {
    const std::string where = k + "[" + std::to_string(i) + "]";
    const auto& p = arr[i];
    if (!p.is_array() || p.as_array().size() != 3) {
      throw LineError{where + ": expected a point [x, y, z] (an array of 3 numbers)"};
    }
    Vec3<double> q;
    for (int c = 0; c < 3; ++c) {
      const auto& x = p.as_array()[static_cast<std::size_t>(c)];
      if (!x.is_number()) {
        throw LineError{where + ": coordinate " + std::to_string(c) + " is " + kind_name(x) + ", not a number"};
      }
      q[c] = x.as_double();
    }
    s.vertices.push_back(q);
  }
  return s;
}

json::Value error_object(json::Value id, std::size_t line_number, const std::string& message) {
  return json::Value(json::Object{{"id", std::move(id)},
                                  {"error", "line " + std::to_string(line_number) + ": " + message}});
}

}  // namespace

json::Value batch_line(std::string_view line, std::size_t line_number, const RunConfig& cfg) {
  json::Value doc;
  try {
    doc = json::parse(line);
  } catch (const json::ParseError& e) {
    return error_object(nullptr, line_number, std::string("invalid JSON at column ") + std::to_string(e.column()) +
                                                  ": " + e.problem());
  }
  if (!doc.is_object()) return error_object(nullptr, line_number, std::string("expected a JSON object, got ") + kind_name(doc));
  json::Value id;
  const json::Value* idp = doc.find("id");
  if (idp && (idp->is_number() || idp->is_string())) id = *idp;
  try {
    if (!idp) throw LineError{"missing key \"id\""};
    if (!idp->is_number() && !idp->is_string()) {
      throw LineError{std::string("\"id\" must be a number or a string, got ") + kind_name(*idp)};
    }
    const io::ShapeData a = points_from_json(doc.find("a"), "a");
    const io::ShapeData b = points_from_json(doc.find("b"), "b");
    const RunOutcome r = run_sat(a, b, nullptr, cfg);
    return batch_result_json(id, r);
  } catch (const LineError& e) {
    return error_object(id, line_number, e.message);
  } catch (const std::bad_alloc&) {
    return error_object(id, line_number, "out of memory");
  } catch (const std::exception& e) {
    return error_object(id, line_number, e.what());
  }
}

BatchSummary run_batch(std::istream& in, std::ostream& out, const RunConfig& cfg) {
  BatchSummary sum;
  std::string line;
  std::size_t n = 0;
  while (std::getline(in, line)) {
    ++n;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.find_first_not_of(" \t\r\n") == std::string::npos) continue;
    ++sum.queries;
    const json::Value v = batch_line(line, n, cfg);
    if (v.find("error")) ++sum.errors;
    out << json::write(v) << '\n';
    out.flush();
  }
  return sum;
}

}  // namespace sepax::cli

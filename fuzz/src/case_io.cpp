// Text I/O of fuzz cases (see sepax/fuzz/case.hpp for the format).
#include <sepax/fuzz/case.hpp>

#include <charconv>
#include <cstdio>
#include <fstream>
#include <istream>
#include <ostream>
#include <sstream>

#include <sepax/error.hpp>

namespace sepax::fuzz {

void round_to_float(ShapeSpec& s) {
  // Through a volatile float: g++ 12 -O2 (SLP vectorizer) drops the in-place
  // double -> float -> double round trip on Eigen 3-vectors (found by
  // tests/fuzz/case_io_test.cpp; -fno-tree-slp-vectorize or clang keep it).
  for (auto& v : s.vertices)
    for (int c = 0; c < 3; ++c) {
      volatile float f = static_cast<float>(v[c]);
      v[c] = static_cast<double>(f);
    }
}

static std::string fmt(double x) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.9g", x);
  return buf;
}

static void write_shape(std::ostream& out, const char* name, const ShapeSpec& s) {
  out << "shape " << name << "\n";
  for (const auto& v : s.vertices) out << "v " << fmt(v[0]) << " " << fmt(v[1]) << " " << fmt(v[2]) << "\n";
  for (const auto& f : s.faces) {
    out << "f";
    for (int i : f) out << " " << i;
    out << "\n";
  }
  out << "end\n";
}

void write_case(std::ostream& out, const FuzzCase& c, const std::string& comment) {
  std::istringstream lines(comment);
  for (std::string l; std::getline(lines, l);) out << "# " << l << "\n";
  out << "sepax-fuzz-case 1\n";
  out << "family " << c.family << "\n";
  out << "seed " << c.seed << "\n";
  write_shape(out, "A", c.a);
  write_shape(out, "B", c.b);
}

FuzzCase read_case(std::istream& in, const std::string& name) {
  FuzzCase c;
  ShapeSpec* cur = nullptr;
  bool header = false, have_a = false, have_b = false;
  std::string line;
  std::size_t lineno = 0;
  auto fail = [&](const std::string& what) {
    throw InvalidInput(ErrorCode::Parse, name + ":" + std::to_string(lineno) + ": " + what);
  };
  while (std::getline(in, line)) {
    ++lineno;
    if (auto h = line.find('#'); h != std::string::npos) line.resize(h);
    std::istringstream ls(line);
    std::string key;
    if (!(ls >> key)) continue;
    if (!header) {
      int version = 0;
      if (key != "sepax-fuzz-case" || !(ls >> version) || version != 1)
        fail("expected the header 'sepax-fuzz-case 1'");
      header = true;
    } else if (key == "family") {
      if (!(ls >> c.family)) fail("'family' needs a name");
    } else if (key == "seed") {
      if (!(ls >> c.seed)) fail("'seed' needs an unsigned integer");
    } else if (key == "shape") {
      std::string which;
      ls >> which;
      if (cur) fail("'shape' inside a shape (missing 'end')");
      if (which == "A") {
        cur = &c.a;
        have_a = true;
      } else if (which == "B") {
        cur = &c.b;
        have_b = true;
      } else {
        fail("'shape' must be followed by A or B");
      }
    } else if (key == "v") {
      if (!cur) fail("vertex outside a shape");
      double x, y, z;
      if (!(ls >> x >> y >> z)) fail("a vertex needs three numbers");
      cur->vertices.emplace_back(x, y, z);
    } else if (key == "f") {
      if (!cur) fail("face outside a shape");
      std::vector<int> f;
      // (each entry whole: `ls >> long` stopped silently at an index too large for a long)
      for (std::string entry; ls >> entry;) {
        long i = 0;
        const char* const last = entry.data() + entry.size();
        const auto [end, ec] = std::from_chars(entry.data(), last, i);
        if (end != last || (ec != std::errc() && ec != std::errc::result_out_of_range))
          fail("a face is a list of vertex indices ('" + entry + "' is not one)");
        if (ec == std::errc::result_out_of_range || i < 0 || i >= static_cast<long>(cur->vertices.size()))
          fail("face refers to vertex " + entry + ", but only " + std::to_string(cur->vertices.size()) +
               " vertices are defined above it");
        f.push_back(static_cast<int>(i));
      }
      cur->faces.push_back(std::move(f));
    } else if (key == "end") {
      if (!cur) fail("'end' outside a shape");
      cur = nullptr;
    } else {
      fail("unknown keyword '" + key + "'");
    }
    std::string extra;
    if (key != "f" && ls >> extra) fail("unexpected '" + extra + "'");
  }
  if (!header) throw InvalidInput(ErrorCode::Parse, name + ": empty file (no 'sepax-fuzz-case 1' header)");
  if (cur) fail("missing 'end'");
  if (!have_a || !have_b) throw InvalidInput(ErrorCode::Parse, name + ": needs both 'shape A' and 'shape B'");
  round_to_float(c.a);
  round_to_float(c.b);
  return c;
}

FuzzCase read_case_file(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InvalidInput(ErrorCode::Parse, path + ": cannot open the file");
  return read_case(in, path);
}

void write_case_file(const std::string& path, const FuzzCase& c, const std::string& comment) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error(path + ": cannot write the file");
  write_case(out, c, comment);
}

}  // namespace sepax::fuzz

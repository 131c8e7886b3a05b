// src/io/ply_reader.cpp -- see ply_reader.hpp.
#include "io/ply_reader.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <iterator>
#include <limits>
#include <optional>
#include <string_view>
#include <system_error>
#include <utility>
#include <vector>

#include <sepax/error.hpp>

#include "io/open_file.hpp"
#include "io/text_input.hpp"

namespace sepax::cli::io {

namespace {

/// A PLY scalar type.
enum class Scalar { Int8, Uint8, Int16, Uint16, Int32, Uint32, Float32, Float64 };

/// The scalar type a header spells, by its old or its sized name.
std::optional<Scalar> scalar_named(std::string_view s) {
  static constexpr std::array<std::pair<std::string_view, Scalar>, 16> kNames{{
      {"char", Scalar::Int8},
      {"int8", Scalar::Int8},
      {"uchar", Scalar::Uint8},
      {"uint8", Scalar::Uint8},
      {"short", Scalar::Int16},
      {"int16", Scalar::Int16},
      {"ushort", Scalar::Uint16},
      {"uint16", Scalar::Uint16},
      {"int", Scalar::Int32},
      {"int32", Scalar::Int32},
      {"uint", Scalar::Uint32},
      {"uint32", Scalar::Uint32},
      {"float", Scalar::Float32},
      {"float32", Scalar::Float32},
      {"double", Scalar::Float64},
      {"float64", Scalar::Float64},
  }};
  for (const auto& [name, type] : kNames)
    if (name == s) return type;
  return std::nullopt;
}

/// Bytes of a scalar in a binary body.
std::size_t size_of(Scalar t) {
  switch (t) {
    case Scalar::Int8:
    case Scalar::Uint8:
      return 1;
    case Scalar::Int16:
    case Scalar::Uint16:
      return 2;
    case Scalar::Int32:
    case Scalar::Uint32:
    case Scalar::Float32:
      return 4;
    case Scalar::Float64:
      return 8;
  }
  return 8;
}

bool is_integer(Scalar t) { return t != Scalar::Float32 && t != Scalar::Float64; }

/// One property of an element: a scalar, or a list (count type, entry type).
struct Property {
  std::string name;
  Scalar type = Scalar::Float32;  // a list's entry type
  bool list = false;
  Scalar count_type = Scalar::Uint8;
};

/// One element of the header: its name, declared count and properties.
struct Element {
  std::string name;
  std::size_t count = 0;
  std::vector<Property> properties;
  std::size_t header_line = 0;
};

enum class Format { Ascii, BinaryLittle, BinaryBig };

/// The parsed header and where the body starts.
struct Header {
  Format format = Format::Ascii;
  std::vector<Element> elements;
  std::size_t body = 0;       // byte offset of the body
  std::size_t body_line = 1;  // line of the body's first byte (ASCII)
};

/// The header's element counts, "vertex 8, face 6".
std::string declared(const Header& h) {
  std::string s;
  for (const Element& e : h.elements) s += (s.empty() ? "" : ", ") + e.name + " " + std::to_string(e.count);
  return s;
}

/// The line [from, end of line) of text, without its '\r' and the offset after its '\n' in next.
std::string_view line_at(std::string_view text, std::size_t from, std::size_t& next) {
  const std::size_t nl = text.find('\n', from);
  const std::size_t end = nl == std::string_view::npos ? text.size() : nl;
  next = nl == std::string_view::npos ? text.size() : nl + 1;
  std::string_view line = text.substr(from, end - from);
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  return line;
}

/// Steps 1 and 2: the header, every element's count bounded by the body's size.
Header read_header(std::string_view text, const std::string& name) {
  Header h;
  const std::string unreadable = "not a readable PLY file: ";
  std::size_t at = 0, line = 0;
  bool ended = false;
  while (at < text.size() && !ended) {
    std::size_t next = 0;
    const std::string_view l = line_at(text, at, next);
    ++line;
    at = next;
    auto fail = [&](const std::string& what) { fail_at(name, line, what); };
    if (l.find('\0') != std::string_view::npos) fail(unreadable + "NUL byte in the header");
    const std::vector<std::string_view> t = tokens(l);
    if (line == 1) {
      if (t.size() != 1 || t[0] != "ply") fail(unreadable + "the first line is not 'ply'");
      continue;
    }
    if (line == 2) {
      if (t.size() != 3 || t[0] != "format")
        fail(unreadable + "the second line is not 'format ascii|binary_little_endian|binary_big_endian 1.0'");
      if (t[1] == "ascii") {
        h.format = Format::Ascii;
      } else if (t[1] == "binary_little_endian") {
        h.format = Format::BinaryLittle;
      } else if (t[1] == "binary_big_endian") {
        h.format = Format::BinaryBig;
      } else {
        fail("unknown PLY format " + shown(t[1]) + " (ascii, binary_little_endian or binary_big_endian)");
      }
      continue;
    }
    if (t.empty()) continue;
    if (t[0] == "comment" || t[0] == "obj_info") continue;
    if (t[0] == "end_header") {
      ended = true;
    } else if (t[0] == "element") {
      if (t.size() != 3) fail("an element line is 'element NAME COUNT'");
      Element e;
      e.name = std::string(t[1]);
      const long long n = quick_integer(t[2]).value_or(-1);
      if (n < 0) fail("bad count " + shown(t[2]) + " for element '" + e.name + "'");
      e.count = static_cast<std::size_t>(n);
      e.header_line = line;
      h.elements.push_back(std::move(e));
    } else if (t[0] == "property") {
      if (h.elements.empty()) fail("a property line before any element line");
      Property p;
      if (t.size() == 5 && t[1] == "list") {
        const auto count_type = scalar_named(t[2]);
        const auto entry_type = scalar_named(t[3]);
        if (!count_type || !is_integer(*count_type))
          fail("a list's count type must be an integer type, not " + shown(t[2]));
        if (!entry_type) fail("unknown property type " + shown(t[3]));
        p.list = true;
        p.count_type = *count_type;
        p.type = *entry_type;
        p.name = std::string(t[4]);
      } else if (t.size() == 3 && t[1] != "list") {
        const auto type = scalar_named(t[1]);
        if (!type) fail("unknown property type " + shown(t[1]));
        p.type = *type;
        p.name = std::string(t[2]);
      } else {
        fail("a property line is 'property TYPE NAME' or 'property list COUNT_TYPE TYPE NAME'");
      }
      h.elements.back().properties.push_back(std::move(p));
    } else {
      fail("unknown header line " + shown(t[0]) + " (element, property, comment, obj_info, end_header)");
    }
  }
  if (!ended) fail_at(name, line == 0 ? 1 : line, unreadable + "no end_header line");
  h.body = at;
  h.body_line = line + 1;
  // Step 2: an instance of an element with a property takes at least one byte of the body.
  const std::size_t bytes = text.size() - h.body;
  std::size_t instances = 0;
  for (const Element& e : h.elements) {
    if (e.properties.empty()) {
      if (e.count > 0)
        fail_at(name, e.header_line, "element '" + e.name + "' has instances but no properties");
      continue;
    }
    instances += std::min(e.count, bytes + 1);
    if (e.count > bytes || instances > bytes) {
      fail_at(name, e.header_line,
              "element '" + e.name + "' declares " + std::to_string(e.count) + " instances, more than the " +
                  std::to_string(bytes) + " bytes after the header hold");
    }
  }
  return h;
}

/// What the body's reader keeps of each property: the vertex's x, y or z, the face's index list, or
/// nothing.
enum class Role { Skip, X, Y, Z, Indices };

/// The roles of element e's properties (vertex: x, y, z required; face: the index list required).
std::vector<Role> roles_of(const Element& e, const std::string& name, bool vertex, bool face) {
  std::vector<Role> roles(e.properties.size(), Role::Skip);
  std::array<bool, 3> have{false, false, false};
  bool indices = false;
  for (std::size_t i = 0; i < e.properties.size(); ++i) {
    const Property& p = e.properties[i];
    if (vertex && !p.list && (p.name == "x" || p.name == "y" || p.name == "z")) {
      const int c = p.name[0] - 'x';
      if (have[static_cast<std::size_t>(c)])
        fail_at(name, e.header_line, "element 'vertex' has two properties " + p.name);
      have[static_cast<std::size_t>(c)] = true;
      roles[i] = static_cast<Role>(static_cast<int>(Role::X) + c);
    }
    if (face && p.list && (p.name == "vertex_indices" || p.name == "vertex_index") && !indices) {
      if (!is_integer(p.type))
        fail_at(name, e.header_line,
                "the face's vertex index list must hold integers, not floating-point numbers");
      indices = true;
      roles[i] = Role::Indices;
    }
  }
  if (vertex && !(have[0] && have[1] && have[2]))
    fail_at(name, e.header_line, "element 'vertex' needs the properties x, y and z");
  if (face && !indices)
    fail_at(name, e.header_line, "element 'face' has no vertex_indices (or vertex_index) list");
  return roles;
}

/// Where the body's reader is (element, instance), for messages: "vertex 3", "face 0".
std::string instance_name(const Element& e, std::size_t i) { return e.name + " " + std::to_string(i); }

/// Step 3 for an ASCII body: one instance a line.
class AsciiBody : public TextPlace {
 public:
  AsciiBody(std::string_view text, const Header& h, const std::string& name)
      : TextPlace(name), text_(text), at_(h.body) {
    line_ = h.body_line - 1;
  }
  /// The tokens of the next non-empty line; fails at the end of the file.
  const std::vector<std::string_view>& next_instance(const std::string& what) {
    while (true) {
      if (at_ >= text_.size()) {
        ++line_;
        fail("the file ends before " + what);
      }
      std::size_t next = 0;
      const std::string_view l = line_at(text_, at_, next);
      at_ = next;
      ++line_;
      if (l.find('\0') != std::string_view::npos) fail("NUL byte in text (is this a binary PLY file?)");
      tokens_ = tokens(l);
      if (!tokens_.empty()) return tokens_;
    }
  }
  /// After the last instance: fails at the first line that is not blank (the header's counts are fewer
  /// than the lines of data: every element would be read short).
  void expect_end(const Header& h) {
    while (at_ < text_.size()) {
      std::size_t next = 0;
      const std::string_view l = line_at(text_, at_, next);
      at_ = next;
      ++line_;
      if (!tokens(l).empty()) fail("more data than the header declares (" + declared(h) + ")");
    }
  }

 private:
  std::string_view text_;
  std::size_t at_;
  std::vector<std::string_view> tokens_;
};

/// Step 3 for a binary body: scalars of either byte order, every read bounded by the data.
class BinaryBody {
 public:
  BinaryBody(std::string_view text, const Header& h, std::string name)
      : text_(text), at_(h.body), big_(h.format == Format::BinaryBig), name_(std::move(name)) {}
  /// The next scalar of type t as a double (exact for every PLY type), or fails naming what.
  double number(Scalar t, const std::string& what) {
    const std::size_t n = size_of(t);
    if (text_.size() - at_ < n) fail("the binary data ends inside " + what, at_);
    std::array<unsigned char, 8> b{};
    std::memcpy(b.data(), text_.data() + at_, n);
    at_ += n;
    if (big_ != (std::endian::native == std::endian::big))
      std::reverse(b.begin(), b.begin() + static_cast<long>(n));
    switch (t) {
      case Scalar::Int8:
        return static_cast<double>(std::bit_cast<std::int8_t>(b[0]));
      case Scalar::Uint8:
        return static_cast<double>(b[0]);
      case Scalar::Int16:
        return static_cast<double>(load<std::int16_t>(b));
      case Scalar::Uint16:
        return static_cast<double>(load<std::uint16_t>(b));
      case Scalar::Int32:
        return static_cast<double>(load<std::int32_t>(b));
      case Scalar::Uint32:
        return static_cast<double>(load<std::uint32_t>(b));
      case Scalar::Float32:
        return static_cast<double>(load<float>(b));
      case Scalar::Float64:
        return load<double>(b);
    }
    return 0;
  }
  /// Skips count scalars of type t, or fails naming what.
  void skip(Scalar t, std::size_t count, const std::string& what) {
    const std::size_t n = size_of(t);
    if (count > (text_.size() - at_) / n) fail("the binary data ends inside " + what, at_);
    at_ += count * n;
  }
  /// Throws the parse error "FILE: what (byte at)".
  [[noreturn]] void fail(const std::string& what, std::size_t at) const {
    throw InvalidInput(ErrorCode::Parse, name_ + ": " + what + " (byte " + std::to_string(at) + ")");
  }
  /// After the last instance: fails if bytes other than white space are left (the header's counts are
  /// fewer than the data holds).
  void expect_end(const Header& h) const {
    const std::string_view rest = text_.substr(at_);
    if (rest.find_first_not_of(" \t\r\n") != std::string_view::npos)
      fail(std::to_string(rest.size()) + " bytes after the data the header declares (" + declared(h) + ")",
           at_);
  }
  /// Bytes left in the body.
  std::size_t left() const { return text_.size() - at_; }
  std::size_t offset() const { return at_; }

 private:
  template <class X>
  static X load(const std::array<unsigned char, 8>& b) {
    X x;
    std::memcpy(&x, b.data(), sizeof x);
    return x;
  }
  std::string_view text_;
  std::size_t at_;
  bool big_;
  std::string name_;
};

/// A face's vertex index (an integer of the file's index type), in [0, vertex count), else the error
/// names it.
template <class Fail>
int vertex_index(long long v, std::size_t vertices, std::size_t face, const Fail& fail) {
  if (v < 0) fail("face " + std::to_string(face) + ": vertex index " + std::to_string(v) + " is negative");
  if (static_cast<unsigned long long>(v) >= vertices)
    fail("face " + std::to_string(face) + ": vertex index " + std::to_string(v) +
         " is out of range (the file has " + std::to_string(vertices) + " vertices)");
  return static_cast<int>(v);
}

/// A vertex coordinate of a binary body: finite, else the error names it.
template <class Fail>
double coordinate(double v, int c, std::size_t vertex, const Fail& fail) {
  if (!std::isfinite(v))
    fail("coordinate " + std::string(1, "xyz"[c]) + " of vertex " + std::to_string(vertex) +
         " is not finite: NaN and infinity are not allowed");
  return v;
}

/// The name and value range of an integer scalar type (false for float and double).
bool integer_range(Scalar t, const char*& name, long long& lo, long long& hi) {
  switch (t) {
    case Scalar::Int8:
      name = "char", lo = -128, hi = 127;
      return true;
    case Scalar::Uint8:
      name = "uchar", lo = 0, hi = 255;
      return true;
    case Scalar::Int16:
      name = "short", lo = -32768, hi = 32767;
      return true;
    case Scalar::Uint16:
      name = "ushort", lo = 0, hi = 65535;
      return true;
    case Scalar::Int32:
      name = "int", lo = -2147483648LL, hi = 2147483647;
      return true;
    case Scalar::Uint32:
      name = "uint", lo = 0, hi = 4294967295LL;
      return true;
    default:
      return false;
  }
}

/// v, an integer read from an ASCII body, if its property's integer type holds it (an error naming the
/// value and the type otherwise, as a binary file could not store it); any value for float and double.
template <class What>
long long in_type_range(const TextPlace& place, long long v, Scalar type, const What& what) {
  const char* name = nullptr;
  long long lo = 0, hi = 0;
  if (integer_range(type, name, lo, hi) && (v < lo || v > hi))
    place.fail("value " + std::to_string(v) + " for " + what() + " is out of the range of its type " + name +
               " (" + std::to_string(lo) + " to " + std::to_string(hi) + ")");
  return v;
}

/// An integer of an ASCII body that its property's integer type holds (in_type_range).
template <class What>
long long ascii_integer(const TextPlace& place, std::string_view token, Scalar type, const What& what) {
  return in_type_range(place, parse_integer(place, token, what), type, what);
}

/// A number of an ASCII body as its property's type holds it: a float property's value is the float
/// nearest the text (as a binary file would store it), an integer property's an integer in its type's
/// range, a double property's the double nearest the text.
template <class What>
double ascii_number(const TextPlace& place, std::string_view token, Scalar type, const What& what) {
  const char* name = nullptr;
  long long lo = 0, hi = 0;
  if (integer_range(type, name, lo, hi)) return static_cast<double>(ascii_integer(place, token, type, what));
  if (type == Scalar::Float32) {
    float f = 0;
    const auto r = std::from_chars(token.data(), token.data() + token.size(), f, std::chars_format::general);
    if (!token.empty() && r.ec == std::errc() && r.ptr == token.data() + token.size() && std::isfinite(f))
      return static_cast<double>(f);
    if (r.ec == std::errc::result_out_of_range && r.ptr == token.data() + token.size())
      place.fail("number " + shown(token) + " for " + what() + " is out of the range of a float (its type)");
  }
  return parse_double(place, token, what);
}

/// Step 3: every instance of every element in header order.  read(e, roles, i, p, loop) reads instance i
/// of e (a vertex's coordinates into p, a face's indices into loop) and returns its line (0 in binary);
/// the vertex element's instances become the vertices, the face element's the faces.
template <class ReadInstance>
void read_body(const Header& h, const std::string& name, std::size_t vertex_element, ShapeData& out,
               ReadInstance&& read) {
  for (std::size_t ei = 0; ei < h.elements.size(); ++ei) {
    const Element& e = h.elements[ei];
    const bool vertex = ei == vertex_element;
    const bool face = e.name == "face" && vertex_element < ei;
    const std::vector<Role> roles = roles_of(e, name, vertex, face);
    for (std::size_t i = 0; i < e.count; ++i) {
      Vec3<double> p(0, 0, 0);
      std::vector<int> loop;
      const std::size_t line = read(e, roles, i, p, loop);
      if (vertex) {
        out.vertices.push_back(p);
        out.vertex_lines.push_back(line);
      }
      if (face) {
        out.faces.push_back(std::move(loop));
        out.face_lines.push_back(line);
      }
    }
  }
}

void read_ascii(std::string_view text, const Header& h, const std::string& name, ShapeData& out,
                std::size_t vertex_element) {
  AsciiBody body(text, h, name);
  auto fail = [&](const std::string& what) { body.fail(what); };
  read_body(
      h, name, vertex_element, out,
      [&](const Element& e, const std::vector<Role>& roles, std::size_t i, Vec3<double>& p,
          std::vector<int>& loop) {
        const std::string what = instance_name(e, i);
        const auto& t = body.next_instance(what);
        std::size_t k = 0;
        for (std::size_t pi = 0; pi < e.properties.size(); ++pi) {
          const Property& prop = e.properties[pi];
          if (k >= t.size()) fail(what + " has too few values (" + std::to_string(t.size()) + ")");
          if (!prop.list) {
            const Role r = roles[pi];
            if (r == Role::X || r == Role::Y || r == Role::Z) {
              const int c = static_cast<int>(r) - static_cast<int>(Role::X);
              p[c] = ascii_number(body, t[k], prop.type,
                                  [&] { return "coordinate " + std::string(1, "xyz"[c]) + " of " + what; });
            } else {
              (void)ascii_number(body, t[k], prop.type,
                                 [&] { return "property " + prop.name + " of " + what; });
            }
            ++k;
            continue;
          }
          auto count_what = [&] { return "the count of list " + prop.name + " of " + what; };
          const long long n = parse_integer(body, t[k], count_what);
          const auto after = static_cast<long long>(t.size() - k - 1);
          if (n < 0)
            fail("the count of list " + prop.name + " of " + what + " is negative (" + std::to_string(n) +
                 ")");
          if (n > after)
            fail(what + "'s list " + prop.name + " counts " + std::to_string(n) + " values; its line has " +
                 std::to_string(after) + " after the count");
          (void)in_type_range(body, n, prop.count_type, count_what);  // (the count's type holds it)
          ++k;
          for (long long j = 0; j < n; ++j, ++k) {
            if (roles[pi] == Role::Indices) {
              const long long v =
                  ascii_integer(body, t[k], prop.type, [&] { return "a vertex index of " + what; });
              loop.push_back(vertex_index(v, out.vertices.size(), i, fail));
            } else {
              (void)ascii_number(body, t[k], prop.type, [&] { return "list " + prop.name + " of " + what; });
            }
          }
        }
        if (k != t.size())
          fail(what + " has " + std::to_string(t.size() - k) + " value(s) more than its properties (one " +
               e.name + " a line)");
        return body.line_number();
      });
  body.expect_end(h);
}

void read_binary(std::string_view text, const Header& h, const std::string& name, ShapeData& out,
                 std::size_t vertex_element) {
  BinaryBody body(text, h, name);
  read_body(h, name, vertex_element, out,
            [&](const Element& e, const std::vector<Role>& roles, std::size_t i, Vec3<double>& p,
                std::vector<int>& loop) -> std::size_t {
              const std::string what = instance_name(e, i);
              const std::size_t start = body.offset();
              auto fail = [&](const std::string& message) { body.fail(message, start); };
              for (std::size_t pi = 0; pi < e.properties.size(); ++pi) {
                const Property& prop = e.properties[pi];
                const Role r = roles[pi];
                if (!prop.list) {
                  if (r == Role::X || r == Role::Y || r == Role::Z) {
                    const int c = static_cast<int>(r) - static_cast<int>(Role::X);
                    p[c] = coordinate(body.number(prop.type, what), c, i, fail);
                  } else {
                    body.skip(prop.type, 1, what);
                  }
                  continue;
                }
                const double n = body.number(prop.count_type, what);
                if (n < 0) fail("the count of list " + prop.name + " of " + what + " is negative");
                const auto count = static_cast<std::size_t>(n);
                if (count > body.left() / size_of(prop.type))
                  fail("the count of list " + prop.name + " of " + what + " (" + std::to_string(count) +
                       ") is more than the data left holds");
                if (r != Role::Indices) {
                  body.skip(prop.type, count, what);
                  continue;
                }
                loop.reserve(count);
                for (std::size_t j = 0; j < count; ++j)
                  loop.push_back(vertex_index(static_cast<long long>(body.number(prop.type, what)),
                                              out.vertices.size(), i, fail));
              }
              return 0;
            });
  body.expect_end(h);
}

}  // namespace

ShapeData read_ply(std::istream& in, const std::string& name) {
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) throw InvalidInput(ErrorCode::Parse, name + ": read error");
  if (text.empty()) fail_at(name, 1, "not a readable PLY file: the file is empty");
  const Header h = read_header(text, name);
  std::size_t vertex_element = h.elements.size();
  for (std::size_t i = 0; i < h.elements.size() && vertex_element == h.elements.size(); ++i)
    if (h.elements[i].name == "vertex") vertex_element = i;
  if (vertex_element == h.elements.size() || h.elements[vertex_element].count == 0)
    throw InvalidInput(ErrorCode::Parse, name + ": no vertices in the file");
  for (std::size_t i = 0; i < vertex_element; ++i)
    if (h.elements[i].name == "face")
      fail_at(name, h.elements[i].header_line, "element 'face' comes before element 'vertex'");
  if (h.elements[vertex_element].count > static_cast<std::size_t>(std::numeric_limits<int>::max()))
    fail_at(name, h.elements[vertex_element].header_line, "more vertices than an int index can name");
  ShapeData out;
  out.name = name;
  out.from_file = true;
  out.vertices.reserve(h.elements[vertex_element].count);
  if (h.format == Format::Ascii) {
    read_ascii(text, h, name, out, vertex_element);
  } else {
    read_binary(text, h, name, out, vertex_element);
  }
  for (std::size_t f = 0; f < out.faces.size(); ++f) {
    if (out.faces[f].size() < 3) {
      const std::string what = "face " + std::to_string(f) + " has " + std::to_string(out.faces[f].size()) +
                               " vertices; a face needs at least 3";
      if (out.face_lines[f] > 0) fail_at(name, out.face_lines[f], what);
      throw InvalidInput(ErrorCode::Parse, name + ": " + what);
    }
  }
  // No faces (a PLY point cloud, as scanners write): a point set, to be hulled.
  out.kind = out.faces.empty() ? ShapeData::Kind::Points : ShapeData::Kind::Faces;
  return out;
}

ShapeData read_ply_file(const std::string& path) {
  auto in = open_input(path);
  return read_ply(in, path);
}

}  // namespace sepax::cli::io

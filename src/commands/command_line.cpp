// src/commands/command_line.cpp -- see command_line.hpp.
#include "commands/command_line.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>

#include <sepax/error.hpp>

#include "json/json.hpp"

namespace sepax::cli {

std::optional<double> parse_double(const std::string& s) {
  std::string_view t = s;
  if (!t.empty() && t[0] == '+') t.remove_prefix(1);
  double v = 0;
  const auto r = std::from_chars(t.data(), t.data() + t.size(), v);
  if (t.empty() || t[0] == '+' || r.ec != std::errc() || r.ptr != t.data() + t.size()) return std::nullopt;
  return v;
}

int input_error(std::ostream& out, std::ostream& err, bool json, const std::string& verb,
                const std::string& what) {
  err << "sepax " << verb << ": error: " << what << "\n";
  if (json) out << json::write(json::Value{{"error", what}}) << "\n";
  return kExitInput;
}

std::vector<std::string> arguments(int argc, char** argv) {
  std::vector<std::string> v;
  for (int i = 1; i < argc; ++i) v.emplace_back(argv[i]);
  return v;
}

CommandLine::CommandLine(std::string verb, const std::string& description, std::string footer)
    : app(description, "sepax " + verb), verb_(std::move(verb)) {
  app.set_help_flag("-h,--help", "print this help and exit");
  app.get_formatter()->column_width(36);
  if (!footer.empty()) app.footer(std::move(footer));
}

std::string CommandLine::help() const { return app.help(); }

int CommandLine::usage_error(std::ostream& err, const std::string& what) const {
  err << "sepax " << verb_ << ": " << what << "\n(run 'sepax " << verb_ << " --help' for usage)\n";
  return kExitUsage;
}

namespace {

bool looks_like_option(const std::string& s) { return s.size() > 1 && s[0] == '-' && !parse_double(s); }

// `--pose tx ty tz [qw qx qy qz]`: the rotation is there when the token after
// the translation is a number.  The tokens are joined into one
// `--pose=tx,ty,tz,...` so that CLI11 does not take shape arguments after a
// translation for a rotation.
std::vector<std::string> join_pose_tokens(const std::vector<std::string>& args) {
  std::vector<std::string> out;
  for (std::size_t i = 0; i < args.size(); ++i) {
    if (args[i] == "--") {
      out.insert(out.end(), args.begin() + static_cast<std::ptrdiff_t>(i), args.end());
      break;
    }
    if (args[i] != "--pose") {
      out.push_back(args[i]);
      continue;
    }
    std::vector<std::string> v;
    while (v.size() < 3 && i + 1 < args.size() && !looks_like_option(args[i + 1]) && args[i + 1] != "--")
      v.push_back(args[++i]);
    // (numbers beyond the seventh are taken too, so that pose() reports the count rather than the
    // parser an extra shape argument)
    if (v.size() == 3)
      while (i + 1 < args.size() && parse_double(args[i + 1])) v.push_back(args[++i]);
    if (v.empty()) {
      out.push_back(args[i]);  // CLI11 reports the missing value
      continue;
    }
    std::string joined = "--pose=";
    for (std::size_t k = 0; k < v.size(); ++k) joined += (k ? "," : "") + v[k];
    out.push_back(joined);
  }
  return out;
}

// The option named at the start of a CLI11 message ("--number: ..."), if any.
std::string option_in(const std::string& message) {
  const auto start = message.find("--");
  if (start == std::string::npos) return {};
  auto end = start + 2;
  while (end < message.size() &&
         (std::isalnum(static_cast<unsigned char>(message[end])) || message[end] == '-'))
    ++end;
  return message.substr(start, end - start);
}

}  // namespace

std::optional<int> CommandLine::parse(const std::vector<std::string>& args, std::ostream& out,
                                      std::ostream& err) {
  std::vector<std::string> rev = has_pose_ ? join_pose_tokens(args) : args;
  // `-:FMT` and `-#NAME` are shape arguments (standard input), not short options: they pass CLI11 with
  // a marker in place of the dash, which every positional option turns back into '-'.
  constexpr char kStdinMark = '\x1e';
  for (std::string& a : rev)
    if (a.size() > 1 && a[0] == '-' && (a[1] == ':' || a[1] == '#')) a[0] = kStdinMark;
  for (CLI::Option* o : app.get_options())
    if (o->get_positional())
      o->transform([](std::string v) {
        if (!v.empty() && v[0] == kStdinMark) v[0] = '-';
        return v;
      });
  std::reverse(rev.begin(), rev.end());
  try {
    app.parse(rev);
  } catch (const CLI::CallForHelp&) {
    out << help();
    return kExitOk;
  } catch (const CLI::ExtrasError&) {
    const auto extra = app.remaining();
    const std::string first = extra.empty() ? std::string("?") : extra.front();
    return usage_error(
        err, (looks_like_option(first) ? "unknown option '" : "unexpected argument '") + first + "'");
  } catch (const CLI::ArgumentMismatch& e) {
    const std::string name = option_in(e.what());
    if (std::string_view(e.what()).find(": At Most ") != std::string_view::npos)  // (CLI11's wording)
      return usage_error(err, name + " is given more than once (it takes one value)");
    const auto it = needs_.find(name);
    return usage_error(err, it != needs_.end() ? name + " needs " + it->second : std::string(e.what()));
  } catch (const CLI::ParseError& e) {
    return usage_error(err, e.what());
  }
  return std::nullopt;
}

void CommandLine::add_number(RunConfig& cfg, const std::string& default_text) {
  app.add_option_function<std::string>(
         "--number", [&cfg](const std::string& v) { cfg.number = *parse_number_kind(v); },
         "arithmetic: float, double or exact (GMP rationals); default " + default_text)
      ->type_name("float|double|exact")
      ->check(
          [](const std::string& v) {
            return parse_number_kind(v) ? std::string()
                                        : "unknown number type '" + v + "' (float, double or exact)";
          },
          "");
  describe_value("--number", "a value: float, double or exact");
}

void CommandLine::add_algorithm(RunConfig& cfg) {
  app.add_option_function<std::string>(
         "--algorithm", [&cfg](const std::string& v) { cfg.algorithm = *parse_algorithm_kind(v); },
         "SAT algorithm: brute, gauss or traversal; default gauss")
      ->type_name("brute|gauss|traversal")
      ->check(
          [](const std::string& v) {
            return parse_algorithm_kind(v) ? std::string()
                                           : "unknown algorithm '" + v + "' (brute, gauss or traversal)";
          },
          "");
  describe_value("--algorithm", "a value: brute, gauss or traversal");
}

void CommandLine::add_robust(RunConfig& cfg) {
  app.add_flag_function(
      "--robust", [&cfg](std::int64_t) { cfg.robust = true; },
      "float/double with every decision made by an exact predicate");
}

void CommandLine::add_pose(const std::string& what) {
  has_pose_ = true;
  app.add_option("--pose", pose_text_, what)->type_name("TX TY TZ [QW QX QY QZ]");
  describe_value("--pose", "3 numbers (tx ty tz), optionally followed by 4 (qw qx qy qz)");
}

std::optional<Pose> CommandLine::pose() const {
  if (!app.count("--pose")) return std::nullopt;
  std::vector<std::string> t;
  for (std::size_t start = 0;;) {
    const auto comma = pose_text_.find(',', start);
    t.push_back(pose_text_.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  if (t.size() < 3)
    throw UsageError("--pose needs 3 numbers (tx ty tz), optionally followed by 4 (qw qx qy qz)");
  if (t.size() > 7)
    throw UsageError("--pose takes 3 numbers (tx ty tz) or 7 (tx ty tz qw qx qy qz), not " +
                     std::to_string(t.size()));
  if (t.size() != 3 && t.size() != 7)
    throw UsageError("--pose: a rotation needs 4 numbers (qw qx qy qz) after the translation");
  double v[7] = {0, 0, 0, 1, 0, 0, 0};
  for (std::size_t k = 0; k < t.size(); ++k) {
    const auto x = parse_double(t[k]);
    if (!x) throw UsageError("--pose: '" + t[k] + "' is not a number");
    v[k] = *x;
  }
  try {
    return Pose::make(Vec3<double>(v[0], v[1], v[2]), {v[3], v[4], v[5], v[6]});
  } catch (const InvalidInput& e) {
    throw UsageError(e.what());
  }
}

namespace {

std::optional<std::uint64_t> parse_unsigned(const std::string& s) {
  std::uint64_t v = 0;
  const auto r = std::from_chars(s.data(), s.data() + s.size(), v);
  if (s.empty() || r.ec != std::errc() || r.ptr != s.data() + s.size()) return std::nullopt;
  return v;
}

}  // namespace

CLI::Option* CommandLine::add_unsigned(const std::string& name, std::uint64_t& target,
                                       const std::string& desc) {
  describe_value(name, "a non-negative integer");
  return app
      .add_option_function<std::string>(
          name, [&target](const std::string& v) { target = *parse_unsigned(v); }, desc)
      ->type_name("N")
      ->check(
          [](const std::string& v) {
            return parse_unsigned(v) ? std::string() : "'" + v + "' is not a non-negative integer";
          },
          "");
}

CLI::Option* CommandLine::add_unsigned(const std::string& name, int& target, const std::string& desc,
                                       int max) {
  describe_value(name, "a non-negative integer");
  return app
      .add_option_function<std::string>(
          name, [&target](const std::string& v) { target = static_cast<int>(*parse_unsigned(v)); }, desc)
      ->type_name("N")
      ->check(
          [max](const std::string& v) {
            const auto x = parse_unsigned(v);
            if (!x) return "'" + v + "' is not a non-negative integer";
            if (*x <= static_cast<std::uint64_t>(max)) return std::string();
            return "'" + v + "' is too large" +
                   (max < std::numeric_limits<int>::max() ? " (at most " + std::to_string(max) + ")" : "");
          },
          "");
}

CLI::Option* CommandLine::add_nonnegative(const std::string& name, double& target, const std::string& desc) {
  describe_value(name, "a non-negative number");
  return app
      .add_option_function<std::string>(
          name, [&target](const std::string& v) { target = *parse_double(v); }, desc)
      ->type_name("S")
      ->check(
          [](const std::string& v) {
            const auto x = parse_double(v);
            return x && std::isfinite(*x) && *x >= 0 ? std::string()
                                                     : "'" + v + "' is not a non-negative number";
          },
          "");
}

}  // namespace sepax::cli

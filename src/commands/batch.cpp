// src/commands/batch.cpp -- see batch.hpp.
#include "commands/batch.hpp"

#include <algorithm>
#include <condition_variable>
#include <deque>
#include <exception>
#include <mutex>
#include <new>
#include <string>
#include <thread>
#include <vector>

#include <sepax/error.hpp>

#include "commands/query_output.hpp"
#include "json/json.hpp"

namespace sepax::cli {

namespace {

struct LineError {
  std::string message;
};

io::ShapeData points_from_json(const json::Value& doc, const char* key) {
  const std::string k = key;
  const auto it = doc.find(k);
  if (it == doc.end()) throw LineError{"missing key \"" + k + "\""};
  const json::Value& v = *it;
  if (!v.is_array())
    throw LineError{k + ": expected an array of points [[x,y,z], ...], got " + json::kind_name(v)};
  io::ShapeData s;
  s.kind = io::ShapeData::Kind::Points;
  s.name = k;
  if (v.empty()) throw LineError{k + ": no points"};
  for (std::size_t i = 0; i < v.size(); ++i) {
    const std::string where = k + "[" + std::to_string(i) + "]";
    const auto& p = v[i];
    if (!p.is_array() || p.size() != 3) {
      throw LineError{where + ": expected a point [x, y, z] (an array of 3 numbers)"};
    }
    Vec3<double> q;
    for (int c = 0; c < 3; ++c) {
      const auto& x = p[static_cast<std::size_t>(c)];
      if (!x.is_number()) {
        throw LineError{where + ": coordinate " + std::to_string(c) + " is " + json::kind_name(x) +
                        ", not a number"};
      }
      q[c] = x.get<double>();
    }
    s.vertices.push_back(q);
  }
  return s;
}

// The output line: the id first, as written in the input, then the rest.
BatchAnswer answer(const std::string& id_text, const json::Value& rest, bool error) {
  std::string body = json::write(rest);  // "{...}"
  std::string text = "{\"id\":" + id_text;
  if (body.size() > 2)
    text += "," + body.substr(1);
  else
    text += "}";
  return {std::move(text), error};
}

BatchAnswer error_answer(const std::string& id_text, std::size_t line_number, const std::string& message) {
  return answer(id_text, json::Value{{"error", "line " + std::to_string(line_number) + ": " + message}},
                true);
}

}  // namespace

int batch_threads(int jobs) {
  if (jobs > 0) return jobs;
  return static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
}

BatchAnswer batch_line(std::string_view line, std::size_t line_number, const BatchOptions& opt) {
  json::Document doc;
  try {
    doc = json::parse_document(line);
  } catch (const json::ParseError& e) {
    return error_answer("null", line_number,
                        "invalid JSON at column " + std::to_string(e.column()) + ": " + e.problem());
  }
  if (!doc.value.is_object())
    return error_answer("null", line_number,
                        std::string("expected a JSON object, got ") + json::kind_name(doc.value));
  std::string id = "null";
  const auto idp = doc.value.find("id");
  if (idp != doc.value.end() && idp->is_number()) id = doc.number_text.at("id");
  if (idp != doc.value.end() && idp->is_string()) id = json::write(*idp);
  try {
    if (idp == doc.value.end()) throw LineError{"missing key \"id\""};
    if (!idp->is_number() && !idp->is_string()) {
      throw LineError{std::string("\"id\" must be a number or a string, got ") + json::kind_name(*idp)};
    }
    const io::ShapeData a = points_from_json(doc.value, "a");
    const io::ShapeData b = points_from_json(doc.value, "b");
    const RunOutcome r = run_sat(a, b, nullptr, opt.cfg);
    return answer(id, batch_result_json(r, opt.manifold), false);
  } catch (const LineError& e) {
    return error_answer(id, line_number, e.message);
  } catch (const std::bad_alloc&) {
    return error_answer(id, line_number, "out of memory");
  } catch (const std::exception& e) {
    return error_answer(id, line_number, e.what());
  }
}

namespace {

bool blank(const std::string& line) { return line.find_first_not_of(" \t\r\n") == std::string::npos; }

// Reads the next non-blank line (without a final '\r'); false at the end.
bool next_query(std::istream& in, std::string& line, std::size_t& number) {
  while (std::getline(in, line)) {
    ++number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (!blank(line)) return true;
  }
  return false;
}

BatchSummary run_sequential(std::istream& in, std::ostream& out, const BatchOptions& opt) {
  BatchSummary sum;
  std::string line;
  std::size_t n = 0;
  while (next_query(in, line, n)) {
    ++sum.queries;
    const BatchAnswer a = batch_line(line, n, opt);
    sum.errors += a.error;
    out << a.text << '\n';
    out.flush();
  }
  return sum;
}

// The reader (this thread) queues lines in a window; `threads` workers answer
// them in any order; a writer thread writes the window's front as soon as it
// is answered.
BatchSummary run_parallel(std::istream& in, std::ostream& out, const BatchOptions& opt, int threads) {
  struct Slot {
    std::string line;
    std::size_t number = 0;
    BatchAnswer answer;
    bool done = false;
  };
  std::deque<Slot> window;  // references stay valid under push_back / pop_front
  std::size_t base = 0;     // input index of window.front()
  std::size_t next = 0;     // next input index to answer
  bool eof = false;
  const std::size_t limit = 64 * static_cast<std::size_t>(threads);
  std::mutex m;
  std::condition_variable cv;
  BatchSummary sum;

  auto worker = [&] {
    std::unique_lock lock(m);
    for (;;) {
      cv.wait(lock, [&] { return next < base + window.size() || eof; });
      if (next >= base + window.size()) return;  // eof and nothing left
      Slot& s = window[next - base];
      ++next;
      lock.unlock();
      BatchAnswer a = batch_line(s.line, s.number, opt);
      lock.lock();
      s.answer = std::move(a);
      s.done = true;
      cv.notify_all();
    }
  };
  auto writer = [&] {
    std::unique_lock lock(m);
    for (;;) {
      cv.wait(lock, [&] { return (!window.empty() && window.front().done) || (eof && window.empty()); });
      if (window.empty()) return;
      BatchAnswer a = std::move(window.front().answer);
      window.pop_front();
      ++base;
      cv.notify_all();
      lock.unlock();
      sum.errors += a.error;
      out << a.text << '\n';
      out.flush();
      lock.lock();
    }
  };
  std::vector<std::thread> pool;
  for (int i = 0; i < threads; ++i) pool.emplace_back(worker);
  std::thread write_thread(writer);
  std::string line;
  std::size_t n = 0;
  try {
    while (next_query(in, line, n)) {
      std::unique_lock lock(m);
      cv.wait(lock, [&] { return window.size() < limit; });
      window.push_back(Slot{std::move(line), n, {}, false});
      ++sum.queries;
      cv.notify_all();
    }
  } catch (...) {
    {
      std::lock_guard lock(m);
      eof = true;
    }
    cv.notify_all();
    for (auto& t : pool) t.join();
    write_thread.join();
    throw;
  }
  {
    std::lock_guard lock(m);
    eof = true;
  }
  cv.notify_all();
  for (auto& t : pool) t.join();
  write_thread.join();
  return sum;
}

}  // namespace

BatchSummary run_batch(std::istream& in, std::ostream& out, const BatchOptions& opt) {
  const int threads = batch_threads(opt.jobs);
  return threads <= 1 ? run_sequential(in, out, opt) : run_parallel(in, out, opt, threads);
}

}  // namespace sepax::cli

// shards.cpp: parts of a class and the record that joins them (shards.h).
#include "grader/shards.h"

#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>

namespace jello::grader {

Shard parseShard(const std::string& text) {
  Shard shard;
  char slash = 0, rest = 0;
  std::istringstream in(text);
  if (!(in >> shard.part >> slash >> shard.parts) || slash != '/' || (in >> rest) ||
      shard.parts < 1 || shard.part < 1 || shard.part > shard.parts)
    throw std::invalid_argument("--shard " + text + ": K/N expected, 1 <= K <= N (e.g. 2/3)");
  return shard;
}

bool inShard(const std::string& name, const Shard& shard) {
  std::uint64_t hash = 14695981039346656037ull;
  for (unsigned char c : name) hash = (hash ^ c) * 1099511628211ull;
  return static_cast<int>(hash % static_cast<std::uint64_t>(shard.parts)) == shard.part - 1;
}

std::string gradedRecord(const std::vector<Graded>& graded, std::uint64_t seed, bool strict) {
  nlohmann::json record = {
      {"seed", seed}, {"strict", strict}, {"submissions", nlohmann::json::array()}};
  for (const Graded& g : graded) {
    nlohmann::json results = nlohmann::json::array();
    for (const CheckResult& r : g.results) {
      results.push_back({{"check", r.check},
                         {"grade", static_cast<int>(r.grade)},
                         {"diagnosis", r.diagnosis},
                         {"notes", r.notes},
                         {"figure", r.figure}});
    }
    record["submissions"].push_back({{"path", g.submission.path},
                                     {"name", g.submission.name},
                                     {"how", g.how},
                                     {"log", g.buildLog},
                                     {"seconds", g.seconds},
                                     {"results", results}});
  }
  // Invalid UTF-8 (a compiler quoting a student's bytes) is replaced, never a failure.
  return record.dump(1, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
}

GradedRecord readGradedRecord(const std::string& dir) {
  std::string path = dir + "/" + kRecordName;
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot read (not a report folder of ./grade?)");
  GradedRecord out;
  try {
    nlohmann::json record = nlohmann::json::parse(in);
    out.seed = record.at("seed").get<std::uint64_t>();
    out.strict = record.at("strict").get<bool>();
    for (const auto& s : record.at("submissions")) {
      Graded g;
      g.submission.path = s.at("path").get<std::string>();
      g.submission.name = s.at("name").get<std::string>();
      g.how = s.at("how").get<std::string>();
      g.buildLog = s.at("log").get<std::string>();
      g.seconds = s.at("seconds").get<double>();
      for (const auto& r : s.at("results")) {
        int grade = r.at("grade").get<int>();
        if (grade < 0 || grade > static_cast<int>(Grade::Info))
          throw std::runtime_error("a grade out of range");
        CheckResult result{r.at("check").get<std::string>(), static_cast<Grade>(grade),
                           r.at("diagnosis").get<std::string>(),
                           r.at("notes").get<std::vector<std::string>>(),
                           r.at("figure").get<double>()};
        g.results.push_back(std::move(result));
      }
      out.graded.push_back(std::move(g));
    }
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error(path + ": not a record of ./grade (" + e.what() + ")");
  }
  return out;
}

}  // namespace jello::grader

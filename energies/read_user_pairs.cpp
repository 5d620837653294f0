#include "energies/read_user_pairs.h"

#include <yaml-cpp/yaml.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "core/ends_with.h"
#include "core/errors.h"

namespace unfold {
namespace {

UserPair make_pair(const double (&v)[5], int num_vertices, const std::string& where) {
  for (double x : v)
    if (!std::isfinite(x)) throw InputError(where + ": non-finite value");
  for (int k = 0; k < 2; ++k)
    if (v[k] != std::floor(v[k]) || v[k] < 0 || v[k] >= num_vertices) {
      std::ostringstream what;
      what << where << ": vertex index " << v[k] << " is not in [0, " << num_vertices << ")";
      throw InputError(what.str());
    }
  UserPair p;
  p.i = int(v[0]);
  p.j = int(v[1]);
  if (p.i == p.j) throw InputError(where + ": a pair needs two different vertices");
  p.t = Eigen::Vector3d(v[2], v[3], v[4]);
  return p;
}

std::vector<UserPair> read_yaml(const std::string& path, int num_vertices) {
  YAML::Node root;
  try {
    root = YAML::LoadFile(path);
  } catch (const YAML::Exception& e) {
    throw InputError("user pairs '" + path + "': invalid YAML: " + e.msg);
  }
  if (!root.IsSequence()) throw InputError("user pairs '" + path + "': expected a list of pairs");
  std::vector<UserPair> pairs;
  for (size_t k = 0; k < root.size(); ++k) {
    const std::string where = "user pairs '" + path + "' entry " + std::to_string(k + 1);
    const YAML::Node& item = root[k];
    double v[5];
    if (!item.IsSequence() || item.size() != 5)
      throw InputError(where + ": expected [i, j, tx, ty, tz]");
    for (size_t c = 0; c < 5; ++c)
      if (!item[c].IsScalar() || !YAML::convert<double>::decode(item[c], v[c]))
        throw InputError(where + ": expected numbers");
    pairs.push_back(make_pair(v, num_vertices, where));
  }
  return pairs;
}

std::vector<UserPair> read_csv(const std::string& path, int num_vertices) {
  std::ifstream in(path);
  std::vector<UserPair> pairs;
  std::string line;
  bool seen_content = false;
  for (int number = 1; std::getline(in, line); ++number) {
    line = line.substr(0, line.find('#'));
    for (char& c : line)
      if (c == ',' || c == ';' || c == '\t') c = ' ';
    std::istringstream fields(line);
    double v[5];
    int count = 0;
    std::string token;
    bool numeric = true;
    while (fields >> token) {
      char* end = nullptr;
      const double x = std::strtod(token.c_str(), &end);
      if (*end != '\0') numeric = false;
      if (count < 5) v[count] = x;
      ++count;
    }
    if (count == 0) continue;
    if (!numeric && !seen_content) {  // a header before the first pair
      seen_content = true;
      continue;
    }
    seen_content = true;
    const std::string where = "user pairs '" + path + "' line " + std::to_string(number);
    if (!numeric || count != 5) throw InputError(where + ": expected i, j, tx, ty, tz");
    pairs.push_back(make_pair(v, num_vertices, where));
  }
  return pairs;
}

}  // namespace

std::vector<UserPair> read_user_pairs(const std::string& path, int num_vertices) {
  if (!std::ifstream(path).good()) throw InputError("cannot read user pairs file '" + path + "'");
  const std::vector<UserPair> pairs = ends_with(path, ".yaml") || ends_with(path, ".yml")
                                          ? read_yaml(path, num_vertices)
                                          : read_csv(path, num_vertices);
  if (pairs.empty()) throw InputError("user pairs file '" + path + "' holds no pairs");
  return pairs;
}

}  // namespace unfold

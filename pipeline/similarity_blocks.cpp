#include "pipeline/similarity_blocks.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <limits>
#include <map>
#include <sstream>

#include "core/atomic_file.h"

namespace unfold {
namespace fs = std::filesystem;
namespace {

// v2: the ORT normalisation chooses its orientation by silhouette area, so
// the ORT and CMBOF rows of earlier blocks are stale.
constexpr const char* kBlockMagic = "unfold similarity block v2";

std::string shape_header(const std::vector<std::string>& names) {
  std::string line = "shape";
  for (const auto& n : names) line += "," + n;
  return line;
}

// The matrix's rows in the list `rows`, upper triangle, in parallel over pairs.
void compute_rows(const std::vector<RetrievalDescriptor>& d, const std::vector<int>& rows,
                  RetrievalFramework framework, const RetrievalOptions& options,
                  Eigen::MatrixXd* matrix) {
  const int n = int(d.size());
  std::vector<std::pair<int, int>> pairs;
  for (int i : rows)
    for (int j = i + 1; j < n; ++j) pairs.emplace_back(i, j);
#pragma omp parallel for schedule(dynamic)
  for (size_t k = 0; k < pairs.size(); ++k) {
    const auto [i, j] = pairs[k];
    (*matrix)(i, j) = framework_dissimilarity(framework, d[size_t(i)], d[size_t(j)], options);
  }
}

}  // namespace

Eigen::MatrixXd similarity_block(const std::vector<RetrievalDescriptor>& descriptors,
                                 RetrievalFramework framework, int index, int count,
                                 const RetrievalOptions& options) {
  const int n = int(descriptors.size());
  Eigen::MatrixXd block = Eigen::MatrixXd::Constant(n, n, std::numeric_limits<double>::quiet_NaN());
  std::vector<int> rows;
  for (int i = index; i < n; i += count) rows.push_back(i);
  compute_rows(descriptors, rows, framework, options, &block);
  return block;
}

void write_similarity_block(const std::string& path, const Eigen::MatrixXd& block,
                            const std::vector<std::string>& names, int index, int count,
                            const std::string& key) {
  write_file_atomically(path, [&](std::ostream& s) {
    s << kBlockMagic << '\n'
      << key << '\n'
      << shape_header(names) << '\n'
      << std::setprecision(std::numeric_limits<double>::max_digits10);
    for (Eigen::Index i = index; i < block.rows(); i += count) {
      s << names[size_t(i)];
      for (Eigen::Index j = 0; j < block.cols(); ++j) {
        s << ',';
        if (j > i) s << block(i, j);
      }
      s << '\n';
    }
  });
}

int read_similarity_block(const std::string& path, const std::vector<std::string>& names,
                          const std::string& key, Eigen::MatrixXd* matrix) {
  std::ifstream in(path);
  std::string magic, stored_key, header;
  if (!std::getline(in, magic) || magic != kBlockMagic || !std::getline(in, stored_key) ||
      stored_key != key || !std::getline(in, header) || header != shape_header(names))
    return 0;
  std::map<std::string, Eigen::Index> index;
  for (size_t i = 0; i < names.size(); ++i) index[names[i]] = Eigen::Index(i);
  // Parse the whole file first: a malformed one contributes nothing.
  std::vector<std::pair<Eigen::Index, Eigen::VectorXd>> rows;
  for (std::string line; std::getline(in, line);) {
    std::istringstream s(line);
    std::string name, field;
    std::getline(s, name, ',');
    if (!index.count(name)) return 0;
    const Eigen::Index i = index[name];
    Eigen::VectorXd row(Eigen::Index(names.size()));
    for (Eigen::Index j = 0; j < row.size(); ++j) {
      if (!std::getline(s, field, ',') && j > i) return 0;
      if (j <= i) continue;
      char* end = nullptr;
      row(j) = std::strtod(field.c_str(), &end);
      if (field.empty() || *end != '\0' || !std::isfinite(row(j))) return 0;
    }
    rows.emplace_back(i, row);
  }
  for (const auto& [i, row] : rows)
    matrix->row(i).tail(matrix->cols() - i - 1) = row.tail(row.size() - i - 1).transpose();
  return int(rows.size());
}

Eigen::MatrixXd assemble_similarity(const std::vector<RetrievalDescriptor>& descriptors,
                                    const std::vector<std::string>& names,
                                    RetrievalFramework framework, const std::string& block_dir,
                                    const std::string& prefix, const std::string& key,
                                    const RetrievalOptions& options) {
  const int n = int(descriptors.size());
  Eigen::MatrixXd D = Eigen::MatrixXd::Constant(n, n, std::numeric_limits<double>::quiet_NaN());
  std::error_code ec;
  for (fs::directory_iterator it(block_dir, ec), end; !ec && it != end; it.increment(ec))
    if (it->path().filename().string().rfind(prefix + ".", 0) == 0)
      read_similarity_block(it->path().string(), names, key, &D);
  std::vector<int> missing;
  for (int i = 0; i + 1 < n; ++i)
    if (D.row(i).tail(n - i - 1).hasNaN()) missing.push_back(i);
  compute_rows(descriptors, missing, framework, options, &D);
  for (int i = 0; i < n; ++i) {
    D(i, i) = 0;
    for (int j = 0; j < i; ++j) D(i, j) = D(j, i);
  }
  return D;
}

}  // namespace unfold

#include "pipeline/cmbof_vocabulary.h"

#include <algorithm>
#include <cstring>
#include <fstream>
#include <initializer_list>
#include <iomanip>
#include <limits>
#include <sstream>
#include <utility>

#include "core/atomic_file.h"
#include "core/errors.h"

namespace unfold {
namespace {

// v2: learned from features of the silhouette-area orientation (descriptor v3).
constexpr const char* kVocabularyMagic = "unfold cmbof vocabulary v2";

// A 64-bit FNV-1a hash of the byte ranges, in hex.
std::string fnv1a_hex(std::initializer_list<std::pair<const void*, size_t>> ranges) {
  std::uint64_t hash = 14695981039346656037ull;
  for (const auto& [data, bytes] : ranges)
    for (size_t i = 0; i < bytes; ++i)
      hash = (hash ^ static_cast<const unsigned char*>(data)[i]) * 1099511628211ull;
  std::ostringstream s;
  s << std::hex << std::setw(16) << std::setfill('0') << hash;
  return s.str();
}

}  // namespace

Eigen::MatrixXf cmbof_vocabulary(const std::vector<const CmbofFeatures*>& shapes,
                                 const CmbofOptions& options) {
  Eigen::Index total = 0;
  for (const CmbofFeatures* s : shapes) total += s->descriptors.rows();
  if (total == 0) throw UsageError("CMBOF: no SIFT features in any view of any shape");
  const Eigen::Index stride =
      (total + options.training_features - 1) / std::max(1, options.training_features);
  Eigen::MatrixXf sample((total + stride - 1) / stride, 128);
  Eigen::Index index = 0, row = 0;
  for (const CmbofFeatures* s : shapes)
    for (Eigen::Index i = 0; i < s->descriptors.rows(); ++i, ++index)
      if (index % stride == 0) sample.row(row++) = s->descriptors.row(i).cast<float>();
  return learn_vocabulary(sample, options.words, options.kmeans_iterations, 1);
}

std::vector<WordHistogram> cmbof_histograms(const CmbofFeatures& features,
                                            const Eigen::MatrixXf& vocabulary) {
  const Eigen::VectorXi words = nearest_words(vocabulary, features.descriptors.cast<float>());
  std::vector<WordHistogram> histograms;
  for (int v = 0; v < features.views(); ++v) {
    std::vector<int> view(words.data() + features.view_start[size_t(v)],
                          words.data() + features.view_start[size_t(v) + 1]);
    std::sort(view.begin(), view.end());
    WordHistogram h;
    for (int w : view)
      if (!h.empty() && h.back().first == w)
        ++h.back().second;
      else
        h.emplace_back(w, 1);
    histograms.push_back(std::move(h));
  }
  return histograms;
}

std::string vocabulary_fingerprint(const Eigen::MatrixXf& vocabulary) {
  const Eigen::Index size[2] = {vocabulary.rows(), vocabulary.cols()};
  return fnv1a_hex(
      {{size, sizeof size}, {vocabulary.data(), size_t(vocabulary.size()) * sizeof(float)}});
}

std::string features_fingerprint(const CmbofFeatures& features) {
  const SiftDescriptors& d = features.descriptors;
  return fnv1a_hex({{features.view_start.data(), features.view_start.size() * sizeof(int)},
                    {d.data(), size_t(d.size())}});
}

void write_vocabulary(const std::string& path, const Eigen::MatrixXf& vocabulary,
                      const std::string& key) {
  write_file_atomically(path, [&](std::ostream& s) {
    s << kVocabularyMagic << '\n'
      << key << '\n'
      << vocabulary.rows() << ' ' << vocabulary.cols() << '\n'
      << std::setprecision(std::numeric_limits<float>::max_digits10);
    for (Eigen::Index i = 0; i < vocabulary.rows(); ++i) {
      for (Eigen::Index j = 0; j < vocabulary.cols(); ++j) s << (j ? " " : "") << vocabulary(i, j);
      s << '\n';
    }
  });
}

std::optional<Eigen::MatrixXf> read_vocabulary(const std::string& path, const std::string& key) {
  std::ifstream in(path);
  std::string magic, stored_key;
  Eigen::Index rows = -1, cols = -1;
  if (!std::getline(in, magic) || magic != kVocabularyMagic || !std::getline(in, stored_key) ||
      stored_key != key || !(in >> rows >> cols) || rows < 1 || cols != 128 || rows > 1000000)
    return std::nullopt;
  Eigen::MatrixXf vocabulary(rows, cols);
  for (Eigen::Index i = 0; i < rows; ++i)
    for (Eigen::Index j = 0; j < cols; ++j)
      if (!(in >> vocabulary(i, j))) return std::nullopt;
  return vocabulary;
}

}  // namespace unfold

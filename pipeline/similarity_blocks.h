// The similarity (dissimilarity) matrix in blocks of rows, so that the pairs
// spread over a cluster's array tasks like the shapes do (`--shard i/N`): block
// i holds the rows k with k % N == i, each row k the entries (k, j), j > k (the
// matrix is made symmetric from its upper triangle; interleaved rows balance
// the work). Blocks are files; the collecting run fills the matrix from every
// block file that matches its shapes and options, computes the rows no file
// had, and mirrors.
//
// Block file (text): the line "unfold similarity block v2", the framework's
// similarity_key (pipeline/retrieval_descriptors.h), the line "shape,<name>,<name>,...", then
// one line per row "<name>,<value>,...", empty fields for j <= k, values with
// an exact round trip.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "pipeline/retrieval_descriptors.h"

namespace unfold {

/// Rows k % count == index of the upper triangle of the framework's matrix
/// over `descriptors` (in parallel); every other entry NaN.
/// @pre 0 <= index < count
Eigen::MatrixXd similarity_block(const std::vector<RetrievalDescriptor>& descriptors,
                                 RetrievalFramework framework, int index, int count,
                                 const RetrievalOptions& options);

/// Writes the rows k % count == index of `block` (similarity_block) atomically,
/// with `key` (similarity_key) in the header. @throws OutputError
void write_similarity_block(const std::string& path, const Eigen::MatrixXd& block,
                            const std::vector<std::string>& names, int index, int count,
                            const std::string& key);

/// Copies the rows found in a block file into *matrix if its shapes and key
/// are these; a missing or malformed file, or another's, changes nothing.
/// @return the number of rows copied
int read_similarity_block(const std::string& path, const std::vector<std::string>& names,
                          const std::string& key, Eigen::MatrixXd* matrix);

/// The full symmetric matrix (zero diagonal): rows found in the block files in
/// `block_dir` named `<prefix>.*` with this `key`, the others computed here.
Eigen::MatrixXd assemble_similarity(const std::vector<RetrievalDescriptor>& descriptors,
                                    const std::vector<std::string>& names,
                                    RetrievalFramework framework, const std::string& block_dir,
                                    const std::string& prefix, const std::string& key,
                                    const RetrievalOptions& options);

}  // namespace unfold

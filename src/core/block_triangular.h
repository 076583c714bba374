// The block triangular form of a square sparse matrix: the order in which a linear system
// A x = b can be solved group by group, each group a square block whose unknowns depend only
// on its own rows and on groups solved before it (the fine decomposition of Dulmage and
// Mendelsohn, for a structurally nonsingular matrix; Duff, Erisman and Reid, "Direct Methods
// for Sparse Matrices", ch. 6).
//
// Only the pattern of A is read (which entries are not identically zero):
//   1. a perfect matching of rows to columns (augmenting paths); none means that every term of
//      det A has a zero factor: A is singular whatever its entries (structurally singular);
//   2. the columns as a directed graph, column c -> c' when the row matched to c has an entry in
//      column c': c cannot be solved before c';
//   3. its strongly connected components (Tarjan) are the blocks; Tarjan's algorithm emits a
//      component only after every component it reaches, which is the order of solving.
// With P, Q the permutations of rows and columns, P A Q is block lower triangular, so det A is,
// up to its sign, the product of the blocks' determinants. For a mechanism's velocity system the
// blocks are its groups of links solved together (a dyad is a block of 2 or 3 unknowns): a
// symbolic solve by blocks inverts small determinants where Cramer's rule on A inverts one large
// one.
#pragma once

#include <optional>
#include <vector>

namespace linkproof {

/// One square diagonal block: its rows and its columns, each ascending.
struct MatrixBlock {
  std::vector<int> rows, cols;
};

/// The blocks of the square pattern `nonzero` (nonzero[r][c]: entry (r, c) may be non-zero), in
/// an order in which they can be solved one after the other; nullopt if the pattern is
/// structurally singular. Deterministic: the same pattern gives the same blocks.
std::optional<std::vector<MatrixBlock>> block_triangular_form(const std::vector<std::vector<bool>>& nonzero);

}  // namespace linkproof

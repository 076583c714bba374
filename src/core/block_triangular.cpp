#include "core/block_triangular.h"

#include <algorithm>
#include <functional>

#include "linkproof/core/error.h"

namespace linkproof {

namespace {

// Kuhn's augmenting paths: row_of[c] for every column, or nothing if some row cannot be matched.
std::optional<std::vector<int>> perfect_matching(const std::vector<std::vector<bool>>& nonzero) {
  const int n = static_cast<int>(nonzero.size());
  std::vector<int> row_of(static_cast<size_t>(n), -1);
  std::vector<int> seen(static_cast<size_t>(n), -1);
  const std::function<bool(int, int)> augment = [&](int r, int round) {
    for (int c = 0; c < n; ++c) {
      if (!nonzero[static_cast<size_t>(r)][static_cast<size_t>(c)] || seen[static_cast<size_t>(c)] == round) continue;
      seen[static_cast<size_t>(c)] = round;
      int& owner = row_of[static_cast<size_t>(c)];
      if (owner < 0 || augment(owner, round)) {
        owner = r;
        return true;
      }
    }
    return false;
  };
  for (int r = 0; r < n; ++r)
    if (!augment(r, r)) return std::nullopt;
  return row_of;
}

}  // namespace

std::optional<std::vector<MatrixBlock>> block_triangular_form(const std::vector<std::vector<bool>>& nonzero) {
  const int n = static_cast<int>(nonzero.size());
  for (const auto& row : nonzero) LINKPROOF_ASSERT(static_cast<int>(row.size()) == n, "block_triangular_form: not square");
  const std::optional<std::vector<int>> row_of = perfect_matching(nonzero);
  if (!row_of) return std::nullopt;

  // Tarjan's strongly connected components on the columns (n is a mechanism's unknowns: the
  // recursion is shallow).
  std::vector<int> order(static_cast<size_t>(n), -1), low(static_cast<size_t>(n), 0), stack;
  std::vector<bool> on_stack(static_cast<size_t>(n), false);
  std::vector<MatrixBlock> blocks;
  int next = 0;
  const std::function<void(int)> visit = [&](int c) {
    const auto uc = static_cast<size_t>(c);
    order[uc] = low[uc] = next++;
    stack.push_back(c);
    on_stack[uc] = true;
    const auto& row = nonzero[static_cast<size_t>((*row_of)[uc])];
    for (int d = 0; d < n; ++d) {
      const auto ud = static_cast<size_t>(d);
      if (d == c || !row[ud]) continue;
      if (order[ud] < 0) {
        visit(d);
        low[uc] = std::min(low[uc], low[ud]);
      } else if (on_stack[ud]) {
        low[uc] = std::min(low[uc], order[ud]);
      }
    }
    if (low[uc] != order[uc]) return;
    MatrixBlock b;
    for (int d = -1; d != c;) {
      d = stack.back();
      stack.pop_back();
      on_stack[static_cast<size_t>(d)] = false;
      b.cols.push_back(d);
      b.rows.push_back((*row_of)[static_cast<size_t>(d)]);
    }
    std::sort(b.cols.begin(), b.cols.end());
    std::sort(b.rows.begin(), b.rows.end());
    blocks.push_back(std::move(b));
  };
  for (int c = 0; c < n; ++c)
    if (order[static_cast<size_t>(c)] < 0) visit(c);
  return blocks;
}

}  // namespace linkproof

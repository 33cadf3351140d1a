#include "isurface/optimise/optimized_run_comparison.h"

#include <algorithm>
#include <cstdint>

namespace isurface {

namespace {

std::uint32_t lineCount(const std::string& text) {
  std::uint32_t n = static_cast<std::uint32_t>(std::count(text.begin(), text.end(), '\n'));
  if (!text.empty() && text.back() != '\n') ++n;
  return n;
}

}  // namespace

OptimizedLineKeys optimizedLineKeys(const OptimizeResult& result) {
  OptimizedLineKeys keys;
  std::vector<OptimizedPass> passes = result.passes;
  std::sort(passes.begin(), passes.end(), [](const auto& p, const auto& q) { return p.firstLine < q.firstLine; });
  const std::uint32_t newLines = lineCount(result.text);
  std::uint32_t oldLines = 0;
  for (const OptimizedPass& p : passes) oldLines = std::max(oldLines, p.lastLine);
  keys.before.resize(std::size_t(oldLines) + 1);
  keys.after.resize(std::size_t(newLines) + 1);
  for (std::uint32_t line = 0; line <= oldLines; ++line) keys.before[line] = line;
  for (const OptimizedPass& p : passes)
    std::fill(keys.before.begin() + p.firstLine, keys.before.begin() + p.lastLine + 1, p.firstLine);
  // Walk the new program: up to a pass's replacement its lines are old lines moved by the
  // passes before; the replacement is the pass's group.
  std::int64_t shift = 0;  // new line number minus old, between passes
  std::uint32_t line = 1;
  for (const OptimizedPass& p : passes) {
    for (; line < p.newFirstLine && line <= newLines; ++line) keys.after[line] = static_cast<std::uint32_t>(line - shift);
    for (; line <= p.newLastLine && line <= newLines; ++line) keys.after[line] = p.firstLine;
    shift = std::int64_t(p.newLastLine) - std::int64_t(p.lastLine);
  }
  for (; line <= newLines; ++line) keys.after[line] = static_cast<std::uint32_t>(line - shift);
  return keys;
}

RunComparison compareOptimizedRuns(const Trajectory& before, const Trajectory& after, const OptimizeResult& result,
                                   RunComparisonOptions options) {
  OptimizedLineKeys keys = optimizedLineKeys(result);
  options.lineKeyA = std::move(keys.before);
  options.lineKeyB = std::move(keys.after);
  return compareRuns(before, after, options);
}

}  // namespace isurface

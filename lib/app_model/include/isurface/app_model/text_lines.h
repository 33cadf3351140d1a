#pragma once
// A text file (G-code, millions of lines) mapped and indexed by line, for a pane that shows any
// line at once without copying the file.
#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace isurface::app_model {

class TextLines {
 public:
  // Maps the file; throws InputError naming it when it cannot be read.
  explicit TextLines(const std::string& path);
  ~TextLines();
  TextLines(const TextLines&) = delete;
  TextLines& operator=(const TextLines&) = delete;

  std::size_t count() const;                     // physical lines
  std::string_view line(std::size_t oneBased) const;  // without its line end; "" out of range

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// The first line after `from` (1-based; 0: from the top), going round past the end, whose text
// holds `needle`, letter case aside; backwards, the first before it. Nothing when no line does
// (or the needle is empty).
std::optional<std::size_t> findLine(const TextLines& text, std::string_view needle, std::size_t from,
                                    bool backwards = false);

}  // namespace isurface::app_model

#pragma once
// A self-contained HTML document: text escaped, images embedded as data URIs, a style that
// reads on screen and prints. No script, no link to anything outside the file.
#include <string>
#include <string_view>
#include <vector>

namespace isurface::report {

// Characters of a program line a report shows at most (the rest is cut, its length said).
constexpr std::size_t kLongestShownLine = 300;
std::string shownLine(const std::string& text);

std::string escapeHtml(std::string_view text);
std::string base64(std::string_view bytes);
// The URL of the file `fileName` in the document's own folder: "./" and the name with every
// byte but letters, digits and "-._~" percent-encoded. Whatever the name (`javascript:...`,
// `a/../b`, `?`, `#`), the link opens that file and nothing else; escape it for an attribute.
std::string relativeLink(std::string_view fileName);

class HtmlDocument {
 public:
  explicit HtmlDocument(const std::string& title);

  void heading(int level, const std::string& text, const std::string& id = "");
  void paragraph(const std::string& text);
  // A table: the first row is the header.
  void table(const std::vector<std::vector<std::string>>& rows, const std::string& cssClass = "");
  // A PNG, embedded, with its alternative text as caption.
  void image(const std::string& png, const std::string& caption, const std::string& cssClass = "");
  // Lines of G-code with their line numbers; `mark` is highlighted.
  void code(const std::vector<std::pair<std::uint32_t, std::string>>& numberedLines, std::uint32_t mark);
  void openSection(const std::string& id, const std::string& cssClass = "");
  void closeSection();
  void raw(const std::string& html) { body_ += html; }

  std::string finish() const;

 private:
  std::string title_, body_;
};

}  // namespace isurface::report

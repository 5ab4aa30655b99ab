// A small HTML5 document writer: elements are opened and closed through it,
// so the nesting is right by construction, and every text and attribute
// value it is given is escaped (markup_escape.hpp). Only raw() takes markup
// as is: for the SVG our own svg_plot writer made.
#pragma once

#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace frictionref::cli {

// name="value" pairs; values are escaped when written.
using Attributes = std::vector<std::pair<std::string, std::string>>;

class HtmlWriter {
 public:
  // Starts "<!DOCTYPE html>" and <html lang="en">.
  HtmlWriter();

  // <tag attributes>; void elements (meta, br) are written with void_element().
  void open(std::string_view tag, const Attributes& attributes = {});
  // Closes the innermost open element; `tag` must name it (a check on the
  // caller: a mismatch is an internal error).
  void close(std::string_view tag);
  void void_element(std::string_view tag, const Attributes& attributes = {});
  // <tag attributes>text</tag>
  void element(std::string_view tag, std::string_view text, const Attributes& attributes = {});
  void text(std::string_view text);
  // Markup written as is (trusted: made by our own writers).
  void raw(std::string_view markup);

  // Closes <html> and returns the document; every other element must be closed.
  std::string finish();

 private:
  void start_tag(std::string_view tag, const Attributes& attributes);

  std::string out_;
  std::vector<std::string> open_;
};

}  // namespace frictionref::cli

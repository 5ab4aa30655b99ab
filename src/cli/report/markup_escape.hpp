// Text made safe to put inside HTML and inline SVG, as element content or as
// a quoted attribute value: the markup characters become character
// references, and what an HTML parser would refuse or a browser would show
// as garbage (invalid UTF-8, control characters, noncharacters) becomes
// U+FFFD. File names and command lines are user data: they go through here.
#pragma once

#include <string>
#include <string_view>

namespace frictionref::cli {

// & < > " ' as &amp; &lt; &gt; &quot; &#39;; invalid UTF-8 sequences, C0
// controls other than tab and line feed, DEL, C1 controls and Unicode
// noncharacters as U+FFFD; everything else unchanged.
std::string escape_markup(std::string_view text);

}  // namespace frictionref::cli

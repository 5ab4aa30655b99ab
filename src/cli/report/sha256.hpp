// SHA-256 of the candidate file, for the report's provenance (OpenSSL's
// libcrypto: a hash must come from a library that is itself tested).
#pragma once

#include <string>
#include <string_view>

namespace frictionref::cli {

// 64 lower-case hex digits, as sha256sum prints them.
std::string sha256_hex(std::string_view bytes);

}  // namespace frictionref::cli

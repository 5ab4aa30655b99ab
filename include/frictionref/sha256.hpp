// SHA-256 of a file's bytes, for provenance: the candidate file in `report`,
// a ground-motion record in every output's metadata (OpenSSL's libcrypto: a
// hash must come from a library that is itself tested).
#pragma once

#include <string>
#include <string_view>

namespace frictionref {

// 64 lower-case hex digits, as sha256sum prints them.
std::string sha256_hex(std::string_view bytes);

}  // namespace frictionref

// Shards of a parameter study (shard.hpp).
#include "frictionref/shard.hpp"

#include <charconv>
#include <string>
#include <system_error>

#include "frictionref/error.hpp"

namespace frictionref {

Shard::Range Shard::range(std::size_t total) const {
  // floor(i total / count) without forming i total (it may not fit in 64
  // bits): with total = q count + r, it is i q + floor(i r / count), and
  // i r < 10^12.
  const std::size_t q = total / count, r = total % count;
  const auto edge = [&](std::uint64_t i) { return i * q + i * r / count; };
  return {edge(index - 1), edge(index)};
}

void Shard::validate(const std::string& parameter) const {
  if (!(count >= 1 && count <= max_count))
    throw InvalidInput(parameter, to_string(*this), "the number of shards N must be 1 to 10^6");
  if (!(index >= 1 && index <= count))
    throw InvalidInput(parameter, to_string(*this), "the shard I must be 1 to N");
}

Shard Shard::parse(std::string_view text, const std::string& parameter) {
  const std::string whole(text);
  const auto rule = "must be I/N: shard I (1 to N) of N (1 to 10^6), e.g. 3/8";
  const std::size_t slash = text.find('/');
  if (slash == std::string_view::npos) throw InvalidInput(parameter, whole, rule);
  // Digits only: from_chars takes no sign or space, and must use the whole field.
  const auto number = [&](std::string_view field) {
    std::uint64_t value = 0;
    const char* end = field.data() + field.size();
    const auto [ptr, error] = std::from_chars(field.data(), end, value);
    if (field.empty() || error != std::errc() || ptr != end || value > max_count)
      throw InvalidInput(parameter, whole, rule);
    return value;
  };
  Shard shard;
  shard.index = number(text.substr(0, slash));
  shard.count = number(text.substr(slash + 1));
  if (shard.count < 1 || shard.index < 1 || shard.index > shard.count)
    throw InvalidInput(parameter, whole, rule);
  return shard;
}

std::string to_string(const Shard& shard) {
  return std::to_string(shard.index) + "/" + std::to_string(shard.count);
}

}  // namespace frictionref

// Reading a JSON file (a scene, a case, a data table) so that no document can crash or mislead the
// reader: nesting deeper than kMaxJsonDepth levels is refused while parsing (a recursive dump of a
// deeply nested value would overflow the stack), a key given twice in one object is an error (the
// JSON standard leaves it undefined; nlohmann keeps the last silently), and every failure, a number
// overflowing double (1e309) included, is an InputError naming the file.
#pragma once
#include <nlohmann/json.hpp>

#include <filesystem>

#include "io/json_fields.hpp"

namespace geosph {

// Scenes and case files nest about 6 levels deep; 64 leaves room for any hand-written file.
constexpr int kMaxJsonDepth = 64;

nlohmann::json read_json_file(const std::filesystem::path& path);
// The same checks for a document in memory; `file` names it in the messages.
nlohmann::json parse_json_text(const std::string& text, const std::string& file);

}  // namespace geosph

// The scene format's reference, declared by the modules that read it: each section of the scene
// (a JSON object) registers its fields next to its parser (type, allowed values, default, unit and a
// one-line meaning). `geosph scene-reference` prints it as Markdown or as a JSON Schema for editors,
// JsonFields::reject_unknown lists a section's documented fields in its error, and a unit test parses
// every catalogue scene with recording on and fails on any field read that is not documented.
//
// Section tags are the scene's keys: "scene" (the top level), "kernel", "domain", ..., "materials"
// (what every material has), "materials:<model>" (one model's own fields; a tag "a:b" also takes the
// fields of "a"), "bodies", "bodies.motion", "walls.containers", ...
#pragma once
#include <set>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "io/json_fields.hpp"

namespace geosph {

enum class FieldType { Number, Integer, Boolean, Text, Choice, Vector, Texts, Object, Objects, Points, PointLists };

struct FieldDoc {
  std::string key;
  FieldType type;
  std::string allowed;   // e.g. "> 0", "{rest, hydrostatic}", "dimension numbers"
  std::string fallback;  // default as written in the scene; "required" if it has none
  std::string unit;      // "-" for none
  std::string meaning;   // one line
  Range range{};         // numbers: the allowed range (for the JSON Schema)
  std::vector<std::string> choices{};  // choices: the allowed strings
};

struct SectionDoc {
  std::string tag;      // e.g. "material:drucker_prager"
  std::string path;     // where it sits in the scene, e.g. "materials.<name> (model drucker_prager)"
  std::string summary;  // one line
  std::vector<FieldDoc> fields;
};

// Shorthands for the declarations.
FieldDoc number_doc(std::string key, Range r, std::string fallback, std::string unit, std::string meaning);
FieldDoc choice_doc(std::string key, std::vector<std::string> choices, std::string fallback, std::string meaning);

// Registers a section at static initialisation; returns true (for `static const bool x = ...`).
bool register_section(SectionDoc doc);
const std::vector<SectionDoc>& scene_sections();  // in reading order
// The documented keys of a section tag (with the fields of its parent tag "a" for "a:b").
std::vector<std::string> documented_keys(const std::string& tag);
bool is_documented(const std::string& tag, const std::string& key);

std::string scene_reference_markdown();
nlohmann::json scene_reference_schema();

// While a recorder is set, every JsonFields section that checks for unknown fields adds its
// (tag, key) pairs of the fields it read; for the undocumented-field test.
void record_scene_fields(std::set<std::pair<std::string, std::string>>* into);

}  // namespace geosph

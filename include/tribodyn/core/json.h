#ifndef tribodyn_core_json_h
#define tribodyn_core_json_h

#include <map>
#include <memory>
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <utility>
#include <vector>

namespace tribodyn
{
  /**
   * A small JSON value used to write `summary.json`. Objects keep their keys
   * in insertion order so that the file reads in the order the run produced
   * it. Written by nlohmann-json: numbers with the shortest representation
   * that reads back exactly (round-trip), non-finite numbers as null (JSON
   * has no NaN).
   */
  class JsonValue
  {
  public:
    enum class Type
    {
      null,
      boolean,
      number,
      string,
      array,
      object
    };

    JsonValue();
    JsonValue(const double value);
    JsonValue(const int value);
    JsonValue(const unsigned int value);
    JsonValue(const long value);
    JsonValue(const unsigned long value);
    JsonValue(const unsigned long long value);
    JsonValue(const bool value);
    JsonValue(const char *value);
    JsonValue(const std::string &value);

    static JsonValue
    object();
    static JsonValue
    array();

    /// Object access: inserts the key (keeping insertion order) if needed.
    JsonValue &
    operator[](const std::string &key);

    /// Append to an array.
    void
    push_back(const JsonValue &value);

    Type
    type() const;

    /// Serialize with two-space indentation.
    std::string
    dump(const unsigned int indent = 0) const;

  private:
    /// The tree as an nlohmann::ordered_json (the writer behind dump()).
    nlohmann::ordered_json
    to_library() const;

    Type                                           value_type;
    bool                                           bool_value   = false;
    double                                         number_value = 0;
    std::string                                    string_value;
    std::vector<JsonValue>                         array_values;
    std::vector<std::pair<std::string, JsonValue>> object_values;
  };

  /// A JSON array of the numbers in @p values.
  JsonValue
  json_array(const std::vector<double> &values);
} // namespace tribodyn

#endif

#include <cmath>
#include <nlohmann/json.hpp>
#include <tribodyn/core/json.h>

namespace tribodyn
{
  JsonValue::JsonValue()
      : value_type(Type::null)
  {
  }

  JsonValue::JsonValue(const double value)
      : value_type(Type::number)
      , number_value(value)
  {
  }

  JsonValue::JsonValue(const int value)
      : JsonValue(static_cast<double>(value))
  {
  }

  JsonValue::JsonValue(const unsigned int value)
      : JsonValue(static_cast<double>(value))
  {
  }

  JsonValue::JsonValue(const long value)
      : JsonValue(static_cast<double>(value))
  {
  }

  JsonValue::JsonValue(const unsigned long value)
      : JsonValue(static_cast<double>(value))
  {
  }

  JsonValue::JsonValue(const unsigned long long value)
      : JsonValue(static_cast<double>(value))
  {
  }

  JsonValue::JsonValue(const bool value)
      : value_type(Type::boolean)
      , bool_value(value)
  {
  }

  JsonValue::JsonValue(const char *value)
      : value_type(Type::string)
      , string_value(value)
  {
  }

  JsonValue::JsonValue(const std::string &value)
      : value_type(Type::string)
      , string_value(value)
  {
  }


  JsonValue
  JsonValue::object()
  {
    JsonValue v;
    v.value_type = Type::object;
    return v;
  }


  JsonValue
  JsonValue::array()
  {
    JsonValue v;
    v.value_type = Type::array;
    return v;
  }


  JsonValue &
  JsonValue::operator[](const std::string &key)
  {
    if (value_type == Type::null)
      value_type = Type::object;
    if (value_type != Type::object)
      throw std::logic_error("JsonValue: operator[] on a non-object");
    for (auto &entry : object_values)
      if (entry.first == key)
        return entry.second;
    object_values.emplace_back(key, JsonValue());
    return object_values.back().second;
  }


  void
  JsonValue::push_back(const JsonValue &value)
  {
    if (value_type == Type::null)
      value_type = Type::array;
    if (value_type != Type::array)
      throw std::logic_error("JsonValue: push_back on a non-array");
    array_values.push_back(value);
  }


  JsonValue::Type
  JsonValue::type() const
  {
    return value_type;
  }


  nlohmann::ordered_json
  JsonValue::to_library() const
  {
    switch (value_type)
      {
        case Type::null:
          return nullptr;
        case Type::boolean:
          return bool_value;
        case Type::number:
          if (!std::isfinite(number_value))
            return nullptr;
          if (number_value == std::round(number_value)
              && std::abs(number_value) < 1e15)
            return static_cast<long long>(number_value);
          return number_value;
        case Type::string:
          return string_value;
        case Type::array:
          {
            nlohmann::ordered_json a = nlohmann::ordered_json::array();
            for (const auto &v : array_values)
              a.push_back(v.to_library());
            return a;
          }
        case Type::object:
          {
            nlohmann::ordered_json o = nlohmann::ordered_json::object();
            for (const auto &entry : object_values)
              o[entry.first] = entry.second.to_library();
            return o;
          }
      }
    return nullptr;
  }


  std::string
  JsonValue::dump(const unsigned int indent) const
  {
    // nlohmann-json writes numbers with the shortest representation that
    // reads back to the same double (round-trip exact) and escapes strings.
    std::string text = to_library().dump(2);
    if (indent > 0)
      {
        // Nested use: indent every line after the first.
        const std::string pad(indent, ' ');
        std::string       shifted;
        for (const char c : text)
          {
            shifted += c;
            if (c == '\n')
              shifted += pad;
          }
        text = shifted;
      }
    return text;
  }


  JsonValue
  json_array(const std::vector<double> &values)
  {
    JsonValue a = JsonValue::array();
    for (const double v : values)
      a.push_back(v);
    return a;
  }
} // namespace tribodyn

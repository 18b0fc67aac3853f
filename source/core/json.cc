#include <cmath>
#include <iomanip>
#include <sstream>
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


  namespace
  {
    std::string
    escape(const std::string &text)
    {
      std::ostringstream out;
      for (const char c : text)
        switch (c)
          {
            case '"':
              out << "\\\"";
              break;
            case '\\':
              out << "\\\\";
              break;
            case '\n':
              out << "\\n";
              break;
            case '\t':
              out << "\\t";
              break;
            default:
              if (static_cast<unsigned char>(c) < 0x20)
                out << "\\u" << std::hex << std::setw(4) << std::setfill('0')
                    << static_cast<int>(c) << std::dec;
              else
                out << c;
          }
      return out.str();
    }
  } // namespace


  std::string
  JsonValue::dump(const unsigned int indent) const
  {
    const std::string  pad(indent + 2, ' ');
    const std::string  end_pad(indent, ' ');
    std::ostringstream out;
    switch (value_type)
      {
        case Type::null:
          out << "null";
          break;
        case Type::boolean:
          out << (bool_value ? "true" : "false");
          break;
        case Type::number:
          if (std::isfinite(number_value))
            {
              if (number_value == std::round(number_value)
                  && std::abs(number_value) < 1e15)
                out << static_cast<long long>(number_value);
              else
                out << std::setprecision(17) << number_value;
            }
          else
            out << "null";
          break;
        case Type::string:
          out << '"' << escape(string_value) << '"';
          break;
        case Type::array:
          {
            // Arrays of numbers stay on one line (matrices read well).
            bool all_numbers = true;
            for (const auto &v : array_values)
              all_numbers = all_numbers
                            && (v.value_type == Type::number
                                || v.value_type == Type::null);
            if (array_values.empty())
              out << "[]";
            else if (all_numbers)
              {
                out << "[";
                for (unsigned int i = 0; i < array_values.size(); ++i)
                  out << (i > 0 ? ", " : "") << array_values[i].dump(indent);
                out << "]";
              }
            else
              {
                out << "[\n";
                for (unsigned int i = 0; i < array_values.size(); ++i)
                  out << pad << array_values[i].dump(indent + 2)
                      << (i + 1 < array_values.size() ? ",\n" : "\n");
                out << end_pad << "]";
              }
            break;
          }
        case Type::object:
          {
            if (object_values.empty())
              {
                out << "{}";
                break;
              }
            out << "{\n";
            for (unsigned int i = 0; i < object_values.size(); ++i)
              out << pad << '"' << escape(object_values[i].first)
                  << "\": " << object_values[i].second.dump(indent + 2)
                  << (i + 1 < object_values.size() ? ",\n" : "\n");
            out << end_pad << "}";
            break;
          }
      }
    return out.str();
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

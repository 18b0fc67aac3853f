#ifndef tribodyn_core_version_h
#define tribodyn_core_version_h

namespace tribodyn
{
  /// Version of tribodyn and the git revision it was built from (written
  /// at every build: cmake/version.cmake).
  extern const char *const version_string;
  /// Version number alone (stable across commits; used in generated docs).
  constexpr const char *version_number = TRIBODYN_VERSION_NUMBER;
} // namespace tribodyn

#endif

/* NavLink: the one export macro. Every public nl_* function carries NL_API. */
#ifndef NAVLINK_EXPORT_H
#define NAVLINK_EXPORT_H

#if defined(NL_STATIC)
#  define NL_API
#elif defined(_WIN32)
#  if defined(NL_BUILDING_LIBRARY)
#    define NL_API __declspec(dllexport)
#  else
#    define NL_API __declspec(dllimport)
#  endif
#else
#  define NL_API __attribute__((visibility("default")))
#endif

#endif /* NAVLINK_EXPORT_H */

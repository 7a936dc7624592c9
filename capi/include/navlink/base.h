/*
 * navlink/base.h: Ids, statuses and the version: what every other part builds on, and all a game's
 * component header needs to hold NavLink ids.
 * A part of navlink/navlink.h, which includes every part; its opening comment has the conventions.
 */
#ifndef NAVLINK_BASE_H
#define NAVLINK_BASE_H

#include <stddef.h>
#include <stdint.h>

#include "navlink/export.h"
#include "navlink/version.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---------------------------------------------------------------------------------------------
 * Version
 * ------------------------------------------------------------------------------------------- */

/** Semantic version of the library. */
typedef struct nl_version {
    int32_t major;
    int32_t minor;
    int32_t patch;
} nl_version;

/** The version of the loaded library; equals NL_VERSION_MAJOR/MINOR/PATCH of the header it was
 *  built with. A host compares it with its own header's macros to detect a mismatched library.
 *  Thread-safe; never fails. */
NL_API nl_version nl_get_version(void);

/* ---------------------------------------------------------------------------------------------
 * Status
 *
 * A status has a kind part (success, failure, in progress) in the top bits and detail bits below,
 * as Detour's dtStatus: a success may carry NL_STATUS_PARTIAL_RESULT, a failure carries the reason.
 * ------------------------------------------------------------------------------------------- */

typedef uint32_t nl_status;

#define NL_STATUS_FAILURE 0x80000000u     /**< The call failed; the detail bits say why. */
#define NL_STATUS_SUCCESS 0x40000000u     /**< The call succeeded. */
#define NL_STATUS_IN_PROGRESS 0x20000000u /**< Work was accepted and is not finished yet. */
#define NL_STATUS_DETAIL_MASK 0x0fffffffu

#define NL_STATUS_INVALID_ARGUMENT 0x00000001u /**< An argument is null, out of range or not finite. */
#define NL_STATUS_INVALID_HANDLE 0x00000002u   /**< An id is null, stale, or from another world. */
#define NL_STATUS_BUFFER_TOO_SMALL 0x00000004u /**< An output buffer is too small; the count says how many were needed. */
#define NL_STATUS_OUT_OF_MEMORY 0x00000008u    /**< An allocation failed; nothing was changed. */
#define NL_STATUS_CANCELLED 0x00000010u        /**< The work was cancelled by the host. */
#define NL_STATUS_PARTIAL_RESULT 0x00000020u   /**< Success with a result that is not complete. */
#define NL_STATUS_NOT_FOUND 0x00000040u        /**< The thing asked for does not exist (a file, a point on a mesh). */
#define NL_STATUS_INTERNAL_ERROR 0x00000080u   /**< A bug or a failure inside a dependency; please report it. */
#define NL_STATUS_IO_ERROR 0x00000100u         /**< A file could not be read or written. */
#define NL_STATUS_PARSE_ERROR 0x00000200u      /**< A file or string is malformed (OBJ, JSON). */
#define NL_STATUS_VERSION_MISMATCH 0x00000400u /**< A plugin or file version is not supported. */

/** Nonzero if the status is a success (possibly with detail bits such as PARTIAL_RESULT). */
#define NL_SUCCEEDED(status) (((status) & NL_STATUS_SUCCESS) != 0u)
/** Nonzero if the status is a failure. */
#define NL_FAILED(status) (((status) & NL_STATUS_FAILURE) != 0u)

/** A short static English description of a status, e.g. "failure: invalid argument".
 *  The string is owned by the library and lives as long as it is loaded. Thread-safe.
 *  @param[in] status  The status to describe. */
NL_API const char* nl_status_string(nl_status status);

/** The status returned by the most recent nl_* call on the calling thread that returns a status or
 *  takes a world (nl_status_string, nl_get_version, the nl_default_* functions and these two do not
 *  touch the record). Thread-safe; the record is per thread. */
NL_API nl_status nl_get_last_status(void);

/** The message of the most recent nl_* call on the calling thread: empty if it succeeded, else one
 *  line naming the function and the failing argument, e.g.
 *  "nl_mesh_add: def->indices[7] = 120 is out of range (vertex_count = 64)".
 *  Borrowed: valid until the next nl_* call on this thread. Never null. Thread-safe. */
NL_API const char* nl_get_last_error_message(void);

/** Zero-initialises a struct in C and C++ alike (the nl_*_init() functions use it). */
#ifdef __cplusplus
#define NL_ZERO_INIT {}
#else
#define NL_ZERO_INIT {0}
#endif

/** Defines `static inline T name(void)`: a zeroed T with `size` set, for output structs. */
#define NL_DEFINE_OUTPUT_INIT(T, name)          \
    static inline T name(void) {               \
        T value = NL_ZERO_INIT;                 \
        value.size = (uint32_t)sizeof(T);       \
        return value;                           \
    }

/** Largest coordinate magnitude accepted anywhere, in metres. Far beyond any playable space (float
 *  precision is coarser than a metre past 1e7); it keeps every computation inside float range. */
#define NL_COORDINATE_LIMIT 1.0e9f

/* ---------------------------------------------------------------------------------------------
 * Ids: objects are referred to by ids passed by value, {index1, revision}; the all-zero id is
 * null. An id whose object was removed is stale: using it returns NL_STATUS_INVALID_HANDLE.
 * ------------------------------------------------------------------------------------------- */

/** A registered mesh. Zero-initialised is the null id. */
typedef struct nl_mesh_id {
    uint32_t index1;     /**< Slot index + 1; 0 means null. */
    uint32_t revision;   /**< Changes each time the slot is reused; never repeats. */
} nl_mesh_id;

/** A navmesh in a world. Zero-initialised is the null id. */
typedef struct nl_navmesh_id {
    uint32_t index1;
    uint32_t revision;
} nl_navmesh_id;

/** A link in a world. Zero-initialised is the null id. */
typedef struct nl_link_id {
    uint32_t index1;
    uint32_t revision;
} nl_link_id;

/** A queued path request. Zero-initialised is the null ticket. */
typedef struct nl_path_ticket {
    uint32_t index1;
    uint32_t revision;
} nl_path_ticket;

/** An agent in a world. Zero-initialised is the null id. */
typedef struct nl_agent_id {
    uint32_t index1;
    uint32_t revision;
} nl_agent_id;

/** A plugin loaded in a world. Zero-initialised is the null id. */
typedef struct nl_plugin_id {
    uint32_t index1;
    uint32_t revision;
} nl_plugin_id;

#ifdef __cplusplus
} /* extern "C" */
#endif

#endif /* NAVLINK_BASE_H */

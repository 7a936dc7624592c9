/*
 * The hostile cases of navlink/navmesh_file.h: baked navmesh files saved, loaded and described.
 */
#include "hostile_fixtures.h"

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* A's navmesh as a file, malloc'ed. */
static unsigned char* saved_navmesh(size_t* size) {
    unsigned char* file;
    if (NL_FAILED(nl_navmesh_save(A.world, A.navmesh, NULL, 0, size))) fixture_failed("nl_navmesh_save");
    file = (unsigned char*)malloc(*size);
    if (!file || NL_FAILED(nl_navmesh_save(A.world, A.navmesh, file, *size, size))) fixture_failed("nl_navmesh_save");
    return file;
}

static void group_navmesh_save(void) {
    size_t needed = 0;
    unsigned char* file = saved_navmesh(&needed);
    saver_cases("nl_navmesh_save", "out_size", nl_navmesh_save, file, needed, 0);
    free(file);
}

static char g_save_path[256];
static nl_status save_file_id_call(nl_world* w, raw_id id, void* out) {
    (void)out;
    return nl_navmesh_save_file(w, AS(nl_navmesh_id, id), g_save_path);
}

static void group_navmesh_save_file(void) {
    static const id_function f = {"nl_navmesh_save_file", "navmesh", NULL, 0, 0, 0, save_file_id_call, 0};
    static const char* made[] = {"saved.nlnav"};
    make_tmp();
    snprintf(g_save_path, sizeof g_save_path, "%s/saved.nlnav", g_tmp);
    id_cases(&f, RAW(A.navmesh), RAW(A.stale_navmesh), RAW(B.navmesh));
    CASE("nl_navmesh_save_file", "path NULL") {
        EXPECT_INVALID(A.world, nl_navmesh_save_file(A.world, A.navmesh, NULL), "path");
    }
    CASE("nl_navmesh_save_file", "path empty") {
        EXPECT_INVALID(A.world, nl_navmesh_save_file(A.world, A.navmesh, ""), "path");
    }
    CASE("nl_navmesh_save_file", "path in a missing folder") {
        char path[300];
        snprintf(path, sizeof path, "%s/no-such-folder/x.nlnav", g_tmp);
        EXPECT_FAILURE(A.world, nl_navmesh_save_file(A.world, A.navmesh, path), NL_STATUS_IO_ERROR, "no-such-folder");
    }
    CASE("nl_navmesh_save_file", "path a directory") {
        char path[300];
        snprintf(path, sizeof path, "%s/dir.obj", g_tmp);
        EXPECT_FAILURE(A.world, nl_navmesh_save_file(A.world, A.navmesh, path), NL_STATUS_IO_ERROR, "dir.obj");
    }
    CASE("nl_navmesh_save_file", "path writable (allowed: the file is the buffer's)") {
        size_t size = 0;
        unsigned char* file = saved_navmesh(&size);
        FILE* f2;
        unsigned char* read = (unsigned char*)malloc(size + 1);
        size_t got = 0;
        EXPECT_OK(nl_navmesh_save_file(A.world, A.navmesh, g_save_path));
        f2 = fopen(g_save_path, "rb");
        if (f2 && read) {
            got = fread(read, 1, size + 1, f2);
            fclose(f2);
        }
        EXPECT(got == size && memcmp(read, file, size) == 0, "the file holds %u bytes, not the %u saved", (unsigned)got,
               (unsigned)size);
        free(read);
        free(file);
    }
    remove_tmp(made, 1);
}

/* Loads of A's navmesh's file into A's world (the new navmesh removed again by the undo). */
static unsigned char* g_navmesh_file;
static size_t g_navmesh_file_size;
static nl_status load_navmesh_call(nl_world* world, const void* def, void* out) {
    return nl_navmesh_load(world, g_navmesh_file, g_navmesh_file_size, (const nl_navmesh_load_def*)def,
                           (nl_navmesh_id*)out);
}
static nl_status load_navmesh_file_call(nl_world* world, const void* def, void* out) {
    return nl_navmesh_load_file(world, g_save_path, (const nl_navmesh_load_def*)def, (nl_navmesh_id*)out);
}
static const def_function k_navmesh_load = {
    "nl_navmesh_load", load_navmesh_call, sizeof(nl_navmesh_id), remove_navmesh_out, 1, 0, 0};
static const def_function k_navmesh_load_file = {
    "nl_navmesh_load_file", load_navmesh_file_call, sizeof(nl_navmesh_id), remove_navmesh_out, 1, 0, 0};

static const def_case k_load_defs[] = {
    {"def->flags unknown bits", INVALID, "flags", {SET_U32(nl_navmesh_load_def, flags, 0x80u)}},
    {"def->flags NL_NAVMESH_LOAD_SAME_LEVEL (allowed: the level is the one it was built from)",
     ALLOWED,
     NULL,
     {SET_U32(nl_navmesh_load_def, flags, NL_NAVMESH_LOAD_SAME_LEVEL)}},
};

static void load_def_cases(const def_function* f) {
    const nl_navmesh_load_def valid = nl_default_navmesh_load_def();
    def_function_cases(f, &valid, sizeof valid);
    def_cases(f->function, &valid, sizeof valid, k_load_defs, sizeof k_load_defs / sizeof *k_load_defs, def_refuses,
              def_accepts);
    optional_id_cases(f, &valid, sizeof valid, offsetof(nl_navmesh_load_def, carrier), "def->carrier", RAW(A.movable),
                      RAW(A.stale_mesh), RAW(B.movable));
}

static void load_data_fails_with(const void* data, size_t size, nl_status detail, const char* needle) {
    nl_navmesh_id out;
    fill(&out, sizeof out);
    EXPECT_FAILURE(A.world, nl_navmesh_load(A.world, data, size, NULL, &out), detail, needle);
    EXPECT_UNTOUCHED(&out, sizeof out, "out_id");
}

static void group_navmesh_load(void) {
    size_t i;
    unsigned char* bad;
    g_navmesh_file = saved_navmesh(&g_navmesh_file_size);
    load_def_cases(&k_navmesh_load);
    CASE("nl_navmesh_load", "data NULL (size 10)") {
        load_data_fails_with(NULL, 10, NL_STATUS_INVALID_ARGUMENT, "data");
    }
    CASE("nl_navmesh_load", "size huge (data NULL: not read)") {
        load_data_fails_with(NULL, SIZE_MAX, NL_STATUS_INVALID_ARGUMENT, "data");
    }
    CASE("nl_navmesh_load", "size 0 (not a navmesh file)") {
        load_data_fails_with(g_navmesh_file, 0, NL_STATUS_VERSION_MISMATCH, "not a NavLink navmesh file");
    }
    CASE("nl_navmesh_load", "size short (cut in the middle)") {
        load_data_fails_with(g_navmesh_file, g_navmesh_file_size / 2, NL_STATUS_PARSE_ERROR, "truncated");
    }
    CASE("nl_navmesh_load", "size long (a byte past the file)") {
        bad = (unsigned char*)malloc(g_navmesh_file_size + 1);
        if (!bad) exit(2);
        memcpy(bad, g_navmesh_file, g_navmesh_file_size);
        bad[g_navmesh_file_size] = 0;
        load_data_fails_with(bad, g_navmesh_file_size + 1, NL_STATUS_PARSE_ERROR, "extra bytes");
        free(bad);
    }
    CASE("nl_navmesh_load", "data a links JSON file") {
        load_data_fails_with("{\"format\": \"navlink-links\"}", 27, NL_STATUS_VERSION_MISMATCH,
                             "not a NavLink navmesh file");
    }
    CASE("nl_navmesh_load", "data of a newer format version") {
        bad = (unsigned char*)malloc(g_navmesh_file_size);
        if (!bad) exit(2);
        memcpy(bad, g_navmesh_file, g_navmesh_file_size);
        bad[8] = 9;
        load_data_fails_with(bad, g_navmesh_file_size, NL_STATUS_VERSION_MISMATCH, "newer");
        free(bad);
    }
    for (i = 40; i < g_navmesh_file_size; i += g_navmesh_file_size / 7) {
        CASE("nl_navmesh_load", "data with byte %u changed (corrupted)", (unsigned)i) {
            bad = (unsigned char*)malloc(g_navmesh_file_size);
            if (!bad) exit(2);
            memcpy(bad, g_navmesh_file, g_navmesh_file_size);
            bad[i] ^= 0x5a;
            load_data_fails_with(bad, g_navmesh_file_size, NL_STATUS_PARSE_ERROR, "corrupted");
            free(bad);
        }
    }
    free(g_navmesh_file);
}

static nl_status load_navmesh_at(const char* path, void* out) {
    return nl_navmesh_load_file(A.world, path, NULL, (nl_navmesh_id*)out);
}

static void group_navmesh_load_file(void) {
    static const char* made[] = {"saved.nlnav", "bad.nlnav"};
    char path[300];
    make_tmp();
    snprintf(g_save_path, sizeof g_save_path, "%s/saved.nlnav", g_tmp);
    if (NL_FAILED(nl_navmesh_save_file(A.world, A.navmesh, g_save_path))) fixture_failed("nl_navmesh_save_file");
    load_def_cases(&k_navmesh_load_file);
    bad_path_cases("nl_navmesh_load_file", load_navmesh_at, sizeof(nl_navmesh_id), k_bad_paths, BAD_PATH_COUNT);
    CASE("nl_navmesh_load_file", "path an OBJ file (named in the message)") {
        nl_navmesh_id out;
        fill(&out, sizeof out);
        EXPECT_FAILURE(A.world, nl_navmesh_load_file(A.world, g_obj_path, NULL, &out), NL_STATUS_VERSION_MISMATCH,
                       "quad.obj");
        EXPECT_UNTOUCHED(&out, sizeof out, "out_id");
    }
    snprintf(path, sizeof path, "%s/bad.nlnav", g_tmp);
    write_file(path, "NLNAV");
    CASE("nl_navmesh_load_file", "path a 5-byte file") {
        nl_navmesh_id out;
        fill(&out, sizeof out);
        EXPECT_FAILURE(A.world, nl_navmesh_load_file(A.world, path, NULL, &out), NL_STATUS_VERSION_MISMATCH,
                       "bad.nlnav");
        EXPECT_UNTOUCHED(&out, sizeof out, "out_id");
    }
    remove_tmp(made, 2);
}

static void describe_fails_with(const void* data, size_t size, nl_navmesh_file_info* info, char* json, size_t capacity,
                                size_t* length, nl_status detail, const char* needle) {
    EXPECT_FAILURE(NULL, nl_navmesh_file_describe(data, size, info, json, capacity, length), detail, needle);
}

static void group_navmesh_file_describe(void) {
    size_t size = 0, length, needed = 0;
    unsigned char* file = saved_navmesh(&size);
    nl_navmesh_file_info info;
    char json[4096];
    if (NL_FAILED(nl_navmesh_file_describe(file, size, NULL, NULL, 0, &needed)) || needed + 1 > sizeof json)
        fixture_failed("nl_navmesh_file_describe");
    CASE("nl_navmesh_file_describe", "data NULL (size 10)") {
        describe_fails_with(NULL, 10, NULL, NULL, 0, &length, NL_STATUS_INVALID_ARGUMENT, "data");
    }
    CASE("nl_navmesh_file_describe", "size huge (data NULL: not read)") {
        describe_fails_with(NULL, SIZE_MAX, NULL, NULL, 0, &length, NL_STATUS_INVALID_ARGUMENT, "data");
    }
    CASE("nl_navmesh_file_describe", "size 0 (not a navmesh file)") {
        describe_fails_with(file, 0, NULL, NULL, 0, &length, NL_STATUS_VERSION_MISMATCH, "not a NavLink navmesh file");
    }
    CASE("nl_navmesh_file_describe", "size short (truncated)") {
        describe_fails_with(file, size - 1, NULL, NULL, 0, &length, NL_STATUS_PARSE_ERROR, "truncated");
    }
    CASE("nl_navmesh_file_describe", "out_info NULL (allowed: the JSON only)") {
        EXPECT_OK(nl_navmesh_file_describe(file, size, NULL, json, sizeof json, &length));
        EXPECT(length == needed && strstr(json, "\"builder\"") != NULL, "the JSON: %s", json);
    }
    {
        static const char* what[3] = {"0", "small (4)", "large (sizeof + 64: nothing written past the struct)"};
        int k;
        for (k = 0; k < 3; ++k) {
            CASE("nl_navmesh_file_describe", "out_info->size %s", what[k]) {
                unsigned char buffer[sizeof(nl_navmesh_file_info) + 64];
                const uint32_t sizes[3] = {0u, 4u, (uint32_t)sizeof buffer};
                fill(buffer, sizeof buffer);
                memcpy(buffer, &sizes[k], sizeof sizes[k]);
                if (k < 2) {
                    describe_fails_with(file, size, (nl_navmesh_file_info*)buffer, NULL, 0, NULL,
                                        NL_STATUS_INVALID_ARGUMENT, "size");
                    EXPECT_UNTOUCHED(buffer + 4, sizeof buffer - 4, "out_info");
                } else {
                    nl_navmesh_file_info got;
                    EXPECT_OK(nl_navmesh_file_describe(file, size, (nl_navmesh_file_info*)buffer, NULL, 0, NULL));
                    memcpy(&got, buffer, sizeof got);
                    EXPECT(got.version == 1 && got.file_size == size && got.polygon_count > 0, "the info read back");
                    EXPECT_UNTOUCHED(buffer + sizeof got, 64, "the bytes past out_info");
                }
            }
        }
    }
    CASE("nl_navmesh_file_describe", "made_for_json NULL (allowed with capacity 0: measures)") {
        fill(&length, sizeof length);
        EXPECT_OK(nl_navmesh_file_describe(file, size, NULL, NULL, 0, &length));
        EXPECT(length == needed, "out_length = %u", (unsigned)length);
    }
    CASE("nl_navmesh_file_describe", "capacity 0 (a buffer given)") {
        fill(json, sizeof json);
        describe_fails_with(file, size, NULL, json, 0, &length, NL_STATUS_BUFFER_TOO_SMALL, "capacity");
        EXPECT_UNTOUCHED(json, sizeof json, "made_for_json");
        EXPECT(length == needed, "out_length = %u, expected the %u needed", (unsigned)length, (unsigned)needed);
    }
    CASE("nl_navmesh_file_describe", "capacity small (the length: no room for the NUL)") {
        fill(json, sizeof json);
        describe_fails_with(file, size, NULL, json, needed, &length, NL_STATUS_BUFFER_TOO_SMALL, "capacity");
        EXPECT_UNTOUCHED(json, sizeof json, "made_for_json");
        EXPECT(length == needed, "out_length = %u, expected the %u needed", (unsigned)length, (unsigned)needed);
    }
    CASE("nl_navmesh_file_describe", "capacity huge (buffer NULL)") {
        describe_fails_with(file, size, NULL, NULL, SIZE_MAX, &length, NL_STATUS_INVALID_ARGUMENT, "made_for_json");
    }
    CASE("nl_navmesh_file_describe", "out_length NULL (a buffer given)") {
        fill(json, sizeof json);
        describe_fails_with(file, size, NULL, json, sizeof json, NULL, NL_STATUS_INVALID_ARGUMENT, "out_length");
        EXPECT_UNTOUCHED(json, sizeof json, "made_for_json");
    }
    CASE("nl_navmesh_file_describe", "out_info with out_length NULL (allowed: the info only)") {
        memset(&info, 0, sizeof info);
        info.size = sizeof info;
        EXPECT_OK(nl_navmesh_file_describe(file, size, &info, NULL, 0, NULL));
        EXPECT(info.quantum == 1.0f / 1024.0f && info.link_count > 0, "quantum %g, %u links", (double)info.quantum,
               (unsigned)info.link_count);
    }
    free(file);
}

/* This part's groups, in the order they run. */
static const hostile_group k_groups[] = {
    {"navmesh_save", group_navmesh_save},
    {"navmesh_save_file", group_navmesh_save_file},
    {"navmesh_load", group_navmesh_load},
    {"navmesh_load_file", group_navmesh_load_file},
    {"navmesh_file_describe", group_navmesh_file_describe},
};
const hostile_part hostile_navmesh_file_part = {k_groups, sizeof k_groups / sizeof *k_groups};

/*
 * The coverage check of navlink-abi-hostile-test: reads the public headers, derives the hostile
 * cases each NL_API function needs from its declaration, and reports every one the test did not run.
 * A function added to a header, or a parameter or def field added to one, without its cases fails
 * the test. The headers are read as text: comments and preprocessor lines are dropped, then the
 * declarations are tokenised (they follow the one style of navlink.h: one declarator per field).
 */
/* opendir() and readdir() read the header folders; strict C11 otherwise. */
#define _POSIX_C_SOURCE 200809L

#include "hostile.h"

#include <ctype.h>
#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ---------------------------------------------------------------------------------------------
 * Tokens
 * ------------------------------------------------------------------------------------------- */

typedef struct tokens {
    char** items;
    size_t count, capacity;
} tokens;

static void push_token(tokens* t, const char* begin, size_t length) {
    if (t->count == t->capacity) {
        t->capacity = t->capacity ? 2 * t->capacity : 1024;
        t->items = (char**)realloc(t->items, t->capacity * sizeof *t->items);
        if (!t->items) exit(2);
    }
    t->items[t->count] = (char*)malloc(length + 1);
    if (!t->items[t->count]) exit(2);
    memcpy(t->items[t->count], begin, length);
    t->items[t->count][length] = '\0';
    ++t->count;
}

/* Blanks comments and preprocessor lines (with their continuations) in place. */
static void strip(char* s) {
    char* p = s;
    int line_start = 1;
    while (*p) {
        if (p[0] == '/' && p[1] == '*') {
            char* end = strstr(p + 2, "*/");
            char* stop = end ? end + 2 : p + strlen(p);
            for (; p < stop; ++p)
                if (*p != '\n') *p = ' ';
            continue;
        }
        if (p[0] == '/' && p[1] == '/') {
            for (; *p && *p != '\n'; ++p) *p = ' ';
            continue;
        }
        if (line_start && *p == '#') {
            for (; *p && !(*p == '\n' && p[-1] != '\\'); ++p)
                if (*p != '\n') *p = ' ';
            continue;
        }
        if (*p == '\n')
            line_start = 1;
        else if (!isspace((unsigned char)*p))
            line_start = 0;
        ++p;
    }
}

static void tokenise(const char* s, tokens* t) {
    while (*s) {
        if (isspace((unsigned char)*s)) {
            ++s;
        } else if (isalnum((unsigned char)*s) || *s == '_') {
            const char* b = s;
            while (isalnum((unsigned char)*s) || *s == '_') ++s;
            push_token(t, b, (size_t)(s - b));
        } else if (*s == '"') {
            const char* b = s++;
            while (*s && *s != '"') s += s[0] == '\\' && s[1] ? 2 : 1;
            if (*s) ++s;
            push_token(t, b, (size_t)(s - b));
        } else {
            push_token(t, s, 1);
            ++s;
        }
    }
}

/* ---------------------------------------------------------------------------------------------
 * Declarations: structs with their fields, integer typedefs, NL_API functions with parameters
 * ------------------------------------------------------------------------------------------- */

typedef struct declarator {
    char type[64]; /* the last type word: "float", "nl_mesh_def", "nl_progress_fn" */
    char name[64];
    int pointer;  /* '*' count; a function pointer field counts as 1 */
    int is_const; /* const before the type (the pointee for pointers) */
    int is_array;
} declarator;

typedef struct struct_decl {
    char name[64];
    declarator fields[64];
    size_t field_count;
} struct_decl;

typedef struct function_decl {
    char name[64];
    char header[256]; /* the file that declares it */
    declarator params[12];
    size_t param_count;
} function_decl;

typedef struct declarations {
    struct_decl structs[96];
    size_t struct_count;
    char integers[64][64]; /* typedef'd integer types: nl_status, nl_log_level, ... */
    size_t integer_count;
    function_decl functions[160];
    size_t function_count;
} declarations;

static int is_type_qualifier(const char* w) {
    return strcmp(w, "const") == 0 || strcmp(w, "struct") == 0 || strcmp(w, "volatile") == 0;
}

/* One field or parameter, tokens [b, e). Returns 0 if it is not a declarator (e.g. "void"). */
static int parse_declarator(char** tok, size_t b, size_t e, declarator* d) {
    size_t i, name_at = e;
    memset(d, 0, sizeof *d);
    for (i = b; i < e; ++i) {
        if (strcmp(tok[i], "(") == 0 && i + 2 < e && strcmp(tok[i + 1], "*") == 0) { /* (*name)(...) */
            snprintf(d->name, sizeof d->name, "%s", tok[i + 2]);
            d->pointer = 1;
            snprintf(d->type, sizeof d->type, "%s", "function");
            return 1;
        }
    }
    for (i = b; i < e; ++i) {
        if (strcmp(tok[i], "[") == 0) {
            d->is_array = 1;
            name_at = i;
            break;
        }
    }
    if (name_at - b < 2) return 0; /* "void", or a type without a name; else the name ends it */
    snprintf(d->name, sizeof d->name, "%s", tok[name_at - 1]);
    for (i = b; i < name_at - 1; ++i) {
        if (strcmp(tok[i], "*") == 0)
            ++d->pointer;
        else if (strcmp(tok[i], "const") == 0)
            d->is_const |= d->pointer == 0;
        else if (!is_type_qualifier(tok[i]))
            snprintf(d->type, sizeof d->type, "%s", tok[i]);
    }
    return d->type[0] != '\0' && (isalpha((unsigned char)d->name[0]) || d->name[0] == '_');
}

/* Splits tokens [b, e) at `separator` (outside parentheses and braces) into declarators. */
static size_t parse_list(char** tok, size_t b, size_t e, const char* separator, declarator* out, size_t capacity) {
    size_t n = 0, start = b, i;
    int depth = 0;
    for (i = b; i <= e; ++i) {
        if (i < e && (strcmp(tok[i], "(") == 0 || strcmp(tok[i], "{") == 0)) ++depth;
        if (i < e && (strcmp(tok[i], ")") == 0 || strcmp(tok[i], "}") == 0)) --depth;
        if (i == e || (depth == 0 && strcmp(tok[i], separator) == 0)) {
            if (i > start && n < capacity && parse_declarator(tok, start, i, &out[n])) ++n;
            start = i + 1;
        }
    }
    return n;
}

static size_t matching(char** tok, size_t count, size_t open) {
    const char* o = tok[open];
    const char* c = strcmp(o, "(") == 0 ? ")" : "}";
    int depth = 0;
    size_t i;
    for (i = open; i < count; ++i) {
        if (strcmp(tok[i], o) == 0) ++depth;
        if (strcmp(tok[i], c) == 0 && --depth == 0) return i;
    }
    return count;
}

static const char* k_integer_types[] = {"uint8_t", "uint16_t", "uint32_t", "uint64_t", "int8_t",  "int16_t",
                                        "int32_t", "int64_t",  "size_t",   "int",      "unsigned"};

static int is_integer(const declarations* d, const char* type) {
    size_t i;
    for (i = 0; i < sizeof k_integer_types / sizeof *k_integer_types; ++i)
        if (strcmp(type, k_integer_types[i]) == 0) return 1;
    for (i = 0; i < d->integer_count; ++i)
        if (strcmp(type, d->integers[i]) == 0) return 1;
    return 0;
}

static void parse_header(const char* header, char** tok, size_t count, declarations* d) {
    size_t i;
    for (i = 0; i < count; ++i) {
        if (strcmp(tok[i], "typedef") == 0 && i + 3 < count && strcmp(tok[i + 1], "struct") == 0 &&
            strcmp(tok[i + 3], "{") == 0) {
            const size_t close = matching(tok, count, i + 3);
            if (close + 1 < count && d->struct_count < sizeof d->structs / sizeof *d->structs) {
                struct_decl* s = &d->structs[d->struct_count++];
                snprintf(s->name, sizeof s->name, "%s", tok[close + 1]);
                s->field_count = parse_list(tok, i + 4, close, ";", s->fields, sizeof s->fields / sizeof *s->fields);
            }
            i = close;
        } else if (strcmp(tok[i], "typedef") == 0 && i + 3 < count && strcmp(tok[i + 3], ";") == 0 &&
                   is_integer(d, tok[i + 1]) && d->integer_count < sizeof d->integers / sizeof *d->integers) {
            snprintf(d->integers[d->integer_count++], sizeof d->integers[0], "%s", tok[i + 2]);
        } else if (strcmp(tok[i], "NL_API") == 0) {
            size_t open = i, close;
            while (open < count && strcmp(tok[open], "(") != 0) ++open;
            close = matching(tok, count, open);
            if (open > i + 1 && close < count && d->function_count < sizeof d->functions / sizeof *d->functions) {
                function_decl* f = &d->functions[d->function_count++];
                snprintf(f->name, sizeof f->name, "%s", tok[open - 1]);
                snprintf(f->header, sizeof f->header, "%s", header);
                f->param_count = parse_list(tok, open + 1, close, ",", f->params, sizeof f->params / sizeof *f->params);
            }
            i = close;
        }
    }
}

static const struct_decl* find_struct(const declarations* d, const char* name) {
    size_t i;
    for (i = 0; i < d->struct_count; ++i)
        if (strcmp(d->structs[i].name, name) == 0) return &d->structs[i];
    return NULL;
}

/* Ids are {uint32_t index1; uint32_t revision;}, passed by value. */
static int is_id(const declarations* d, const char* type) {
    const struct_decl* s = find_struct(d, type);
    return s && s->field_count == 2 && strcmp(s->fields[0].name, "index1") == 0 &&
           strcmp(s->fields[1].name, "revision") == 0;
}

static int has_size_field(const struct_decl* s) {
    return s && s->field_count > 0 && strcmp(s->fields[0].name, "size") == 0 && s->fields[0].pointer == 0 &&
           strcmp(s->fields[0].type, "uint32_t") == 0;
}

static int ends_with(const char* s, const char* suffix) {
    const size_t n = strlen(s), m = strlen(suffix);
    return n >= m && strcmp(s + n - m, suffix) == 0;
}

/* ---------------------------------------------------------------------------------------------
 * Requirements
 * ------------------------------------------------------------------------------------------- */

typedef struct requirement {
    const char* function;
    const char* header;
    char subject[128];
    const char* condition;
} requirement;

typedef struct requirements {
    requirement* items;
    size_t count, capacity;
} requirements;

static const char* g_header; /* the declaring file of the function whose requirements are made */

static void need(requirements* r, const char* function, const char* subject, const char* condition) {
    if (r->count == r->capacity) {
        r->capacity = r->capacity ? 2 * r->capacity : 512;
        r->items = (requirement*)realloc(r->items, r->capacity * sizeof *r->items);
        if (!r->items) exit(2);
    }
    r->items[r->count].function = function;
    r->items[r->count].header = g_header;
    snprintf(r->items[r->count].subject, sizeof r->items[0].subject, "%s", subject);
    r->items[r->count].condition = condition;
    ++r->count;
}

static void need_id(requirements* r, const char* function, const char* subject) {
    need(r, function, subject, "null");
    need(r, function, subject, "stale");
    need(r, function, subject, "garbage");
    need(r, function, subject, "foreign");
}

static void need_fields(const declarations* d, requirements* r, const char* function, const struct_decl* s,
                        const char* prefix, int depth) {
    size_t i;
    if (depth > 4) return;
    for (i = has_size_field(s) ? 1 : 0; i < s->field_count; ++i) {
        const declarator* f = &s->fields[i];
        char subject[128];
        snprintf(subject, sizeof subject, "%s%s", prefix, f->name);
        if (f->pointer > 0) {
            need(r, function, subject, "NULL");
            if (strcmp(f->type, "float") == 0 && f->is_const) {
                need(r, function, subject, "NaN");
                need(r, function, subject, "inf");
            }
        } else if (is_id(d, f->type)) {
            need_id(r, function, subject);
        } else if (find_struct(d, f->type)) {
            char nested[sizeof subject + 2];
            snprintf(nested, sizeof nested, "%s.", subject);
            need_fields(d, r, function, find_struct(d, f->type), nested, depth + 1);
        } else if (strcmp(f->type, "float") == 0 || strcmp(f->type, "double") == 0) {
            need(r, function, subject, "NaN");
            need(r, function, subject, "inf");
        } else if (is_integer(d, f->type) && (ends_with(f->name, "_count") || ends_with(f->name, "_length"))) {
            need(r, function, subject, "0");
            need(r, function, subject, "huge");
        }
    }
}

static void need_function(const declarations* d, requirements* r, const function_decl* f) {
    size_t i;
    g_header = f->header;
    need(r, f->name, "", ""); /* at least one case, whatever the parameters */
    for (i = 0; i < f->param_count; ++i) {
        const declarator* p = &f->params[i];
        const struct_decl* s = find_struct(d, p->type);
        if (p->pointer > 0) {
            need(r, f->name, p->name, "NULL");
            if (strcmp(p->type, "float") == 0 && p->is_const) {
                need(r, f->name, p->name, "NaN");
                need(r, f->name, p->name, "inf");
            }
            if (has_size_field(s)) {
                char subject[128];
                snprintf(subject, sizeof subject, "%s->size", p->name);
                need(r, f->name, subject, "0");
                need(r, f->name, subject, "small");
                need(r, f->name, subject, "large");
            }
            if (s && p->is_const) {
                char prefix[128];
                snprintf(prefix, sizeof prefix, "%s->", p->name);
                need_fields(d, r, f->name, s, prefix, 0);
            }
        } else if (is_id(d, p->type)) {
            need_id(r, f->name, p->name);
        } else if (is_integer(d, p->type)) {
            need(r, f->name, p->name, "0");
            need(r, f->name, p->name, "huge");
        } else if (strcmp(p->type, "float") == 0 || strcmp(p->type, "double") == 0) {
            need(r, f->name, p->name, "NaN");
            need(r, f->name, p->name, "inf");
        }
    }
}

/* A case's description as subject and condition: "def->start[1] NaN (...)" -> "def->start", "NaN". */
static void split_description(const char* description, char* subject, size_t subject_size, char* condition,
                              size_t condition_size) {
    size_t n = 0;
    const char* p = description;
    int bracket = 0;
    for (; *p && *p != ' '; ++p) {
        if (*p == '[') bracket = 1;
        if (!bracket && n + 1 < subject_size) subject[n++] = *p;
        if (*p == ']') bracket = 0;
    }
    subject[n] = '\0';
    while (*p == ' ') ++p;
    for (n = 0; *p && *p != ' ' && n + 1 < condition_size; ++p) condition[n++] = *p;
    condition[n] = '\0';
}

static int satisfied(const requirement* q, const case_record* cases, size_t case_count) {
    size_t i;
    for (i = 0; i < case_count; ++i) {
        char subject[128], condition[32];
        if (strcmp(cases[i].function, q->function) != 0) continue;
        if (q->subject[0] == '\0') return 1;
        split_description(cases[i].description, subject, sizeof subject, condition, sizeof condition);
        if (strcmp(subject, q->subject) == 0 && strcmp(condition, q->condition) == 0) return 1;
    }
    return 0;
}

static const coverage_exemption* exempt(const requirement* q, const coverage_exemption* e, size_t n) {
    size_t i;
    for (i = 0; i < n; ++i) {
        if ((e[i].function == NULL || strcmp(e[i].function, q->function) == 0) &&
            strcmp(e[i].subject, q->subject) == 0 && strcmp(e[i].condition, q->condition) == 0)
            return &e[i];
    }
    return NULL;
}

static int read_headers(const char* dir, declarations* d, size_t* header_count) {
    DIR* folder = opendir(dir);
    struct dirent* entry;
    if (!folder) {
        printf("coverage: cannot open the header folder %s\n", dir);
        return 0;
    }
    while ((entry = readdir(folder)) != NULL) {
        char path[4096];
        FILE* f;
        long size;
        char* text;
        tokens t = {NULL, 0, 0};
        size_t k;
        if (!ends_with(entry->d_name, ".h")) continue;
        snprintf(path, sizeof path, "%s/%s", dir, entry->d_name);
        f = fopen(path, "rb");
        if (!f) continue;
        fseek(f, 0, SEEK_END);
        size = ftell(f);
        fseek(f, 0, SEEK_SET);
        text = (char*)calloc((size_t)(size > 0 ? size : 0) + 1, 1);
        if (!text || (size > 0 && fread(text, 1, (size_t)size, f) != (size_t)size)) {
            fclose(f);
            free(text);
            continue;
        }
        fclose(f);
        strip(text);
        tokenise(text, &t);
        parse_header(entry->d_name, t.items, t.count, d);
        for (k = 0; k < t.count; ++k) free(t.items[k]);
        free(t.items);
        free(text);
        ++*header_count;
    }
    closedir(folder);
    return 1;
}

int check_coverage(const char* const* header_dirs, size_t dir_count, const case_record* cases, size_t case_count,
                   const coverage_exemption* exemptions, size_t exemption_count) {
    declarations* d = (declarations*)calloc(1, sizeof *d);
    requirements r = {NULL, 0, 0};
    size_t i, headers = 0, exempted = 0, missing = 0;
    int gaps = 0;
    if (!d) return 1;
    /* Types are looked up once every header is read, so the order of the files does not matter. */
    for (i = 0; i < dir_count; ++i) read_headers(header_dirs[i], d, &headers);
    if (d->function_count == 0) {
        printf("coverage: FAILED: no NL_API function found in %u header folder(s)\n", (unsigned)dir_count);
        free(d);
        return 1;
    }
    for (i = 0; i < d->function_count; ++i) need_function(d, &r, &d->functions[i]);
    for (i = 0; i < r.count; ++i) {
        const coverage_exemption* e;
        if (satisfied(&r.items[i], cases, case_count)) continue;
        if ((e = exempt(&r.items[i], exemptions, exemption_count)) != NULL) {
            ++exempted;
            continue;
        }
        ++missing;
        if (r.items[i].subject[0] == '\0')
            printf("coverage: MISSING: %s has no hostile case at all (declared in %s)\n", r.items[i].function,
                   r.items[i].header);
        else
            printf("coverage: MISSING: %s: no case \"%s %s ...\"\n", r.items[i].function, r.items[i].subject,
                   r.items[i].condition);
    }
    /* Cases of functions no header declares: a typo, or a function removed from the ABI. */
    for (i = 0; i < case_count; ++i) {
        size_t k;
        int declared = 0;
        for (k = 0; k < d->function_count && !declared; ++k)
            declared = strcmp(d->functions[k].name, cases[i].function) == 0;
        if (!declared && (i == 0 || strcmp(cases[i - 1].function, cases[i].function) != 0)) {
            ++gaps;
            printf("coverage: UNKNOWN: cases for %s, which no public header declares\n", cases[i].function);
        }
    }
    /* An exemption that no longer matches a requirement is stale: it would hide nothing, or a typo. */
    for (i = 0; i < exemption_count; ++i) {
        size_t k;
        int used = 0;
        for (k = 0; k < r.count && !used; ++k) {
            used = (exemptions[i].function == NULL || strcmp(exemptions[i].function, r.items[k].function) == 0) &&
                   strcmp(exemptions[i].subject, r.items[k].subject) == 0 &&
                   strcmp(exemptions[i].condition, r.items[k].condition) == 0;
        }
        if (!used) {
            ++gaps;
            printf("coverage: STALE EXEMPTION: %s: %s %s matches no requirement\n",
                   exemptions[i].function ? exemptions[i].function : "*", exemptions[i].subject,
                   exemptions[i].condition);
        }
    }
    gaps += (int)missing;
    for (i = 0; i < exemption_count; ++i)
        printf("coverage: n/a: %s: %s %s: %s\n", exemptions[i].function ? exemptions[i].function : "*",
               exemptions[i].subject, exemptions[i].condition, exemptions[i].reason);
    printf("coverage: %u NL_API functions in %u headers need %u hostile cases: %u present, %u exempt, %d missing\n",
           (unsigned)d->function_count, (unsigned)headers, (unsigned)r.count, (unsigned)(r.count - exempted - missing),
           (unsigned)exempted, (int)missing);
    free(r.items);
    free(d);
    return gaps;
}

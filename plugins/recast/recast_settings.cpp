#include "recast_settings.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "build_failure.h"
#include "io/json_input.h"
#include "recast_builder.h"
#include "util/error.h"
#include "util/excerpt.h"
#include "util/shortest_decimal.h"

namespace nl::recast {
namespace {

// The size of the first version of nl_recast_settings: a caller's struct must hold at least this.
constexpr size_t kFirstSettingsSize = offsetof(nl_recast_settings, reserved) + sizeof(nl_recast_settings::reserved);

// Region sizes are squared into cell areas held in an int.
constexpr double kMaxRegionSize = 46340.0;  // floor(sqrt(INT_MAX))

enum class Kind {
    Float,      // JSON number
    Integer,    // JSON integer (uint32_t field)
    Partition,  // "watershed" / "monotone" / "layers" or 0 / 1 / 2 (uint32_t field)
    Flag,       // JSON boolean (uint8_t field)
    Cells,      // JSON integer (uint32_t field): tile_size 0 or 16..4096, tile_border 0..4096
};

struct Field {
    const char* name;
    Kind kind;
    size_t offset;
};

#define NL_RECAST_FIELD(name, kind) \
    Field { #name, Kind::kind, offsetof(nl_recast_settings, name) }
constexpr Field kFields[] = {
    NL_RECAST_FIELD(cell_size, Float),
    NL_RECAST_FIELD(cell_height, Float),
    NL_RECAST_FIELD(region_min_size, Float),
    NL_RECAST_FIELD(region_merge_size, Float),
    NL_RECAST_FIELD(edge_max_length, Float),
    NL_RECAST_FIELD(edge_max_error, Float),
    NL_RECAST_FIELD(vertices_per_polygon, Integer),
    NL_RECAST_FIELD(detail_sample_distance, Float),
    NL_RECAST_FIELD(detail_sample_max_error, Float),
    NL_RECAST_FIELD(partition, Partition),
    NL_RECAST_FIELD(filter_low_hanging_obstacles, Flag),
    NL_RECAST_FIELD(filter_ledge_spans, Flag),
    NL_RECAST_FIELD(filter_walkable_low_height_spans, Flag),
    NL_RECAST_FIELD(tile_size, Cells),
    NL_RECAST_FIELD(tile_border, Cells),
};
#undef NL_RECAST_FIELD

float& float_field(nl_recast_settings& s, const Field& f) {
    return *reinterpret_cast<float*>(reinterpret_cast<unsigned char*>(&s) + f.offset);
}
uint32_t& uint_field(nl_recast_settings& s, const Field& f) {
    return *reinterpret_cast<uint32_t*>(reinterpret_cast<unsigned char*>(&s) + f.offset);
}
uint8_t& flag_field(nl_recast_settings& s, const Field& f) {
    return *reinterpret_cast<uint8_t*>(reinterpret_cast<unsigned char*>(&s) + f.offset);
}

constexpr int64_t kMaxTileCells = 4096;
constexpr int64_t kMinTileCells = 16;

// What is wrong with a tile's cell count, or "" if nothing.
std::string cells_problem(const std::string& name, int64_t v) {
    std::ostringstream out;
    if (v < 0 || v > kMaxTileCells) {
        out << "must be in 0.." << kMaxTileCells << " cells (got " << v << ")";
    } else if (name == "tile_size" && v != 0 && v < kMinTileCells) {
        out << "must be 0 (one solo mesh) or " << kMinTileCells << ".." << kMaxTileCells << " cells (got " << v << ")";
    }
    return out.str();
}

const char* partition_name(uint32_t p) {
    switch (p) {
        case NL_RECAST_PARTITION_WATERSHED: return "watershed";
        case NL_RECAST_PARTITION_MONOTONE: return "monotone";
        case NL_RECAST_PARTITION_LAYERS: return "layers";
        default: return nullptr;
    }
}

std::string known_keys() {
    std::string out;
    for (const Field& f : kFields) {
        if (!out.empty()) out += ", ";
        out += f.name;
    }
    return out;
}

// What is wrong with a float field's value, or "" if nothing.
std::string float_problem(const std::string& name, double v) {
    std::ostringstream out;
    if (!std::isfinite(v) || std::fabs(v) > FLT_MAX) {
        out << "must be a finite number";
    } else if (name == "cell_size" || name == "cell_height") {
        if (!(v > 0.0)) out << "must be > 0";
    } else if (name == "region_min_size" || name == "region_merge_size") {
        if (!(v >= 0.0 && v <= kMaxRegionSize)) out << "must be in 0.." << kMaxRegionSize << " cells";
    } else if (!(v >= 0.0)) {
        out << "must be >= 0";
    }
    if (out.tellp() > 0) out << " (got " << v << ")";
    return out.str();
}

// What is wrong with field `f` of `s`, or "" if nothing.
std::string field_problem(nl_recast_settings& s, const Field& f) {
    std::ostringstream out;
    switch (f.kind) {
        case Kind::Float: return float_problem(f.name, float_field(s, f));
        case Kind::Integer: {
            const uint32_t v = uint_field(s, f);
            if (v < 3 || v > 6) out << "must be in 3..6 (got " << v << ")";
            break;
        }
        case Kind::Partition: {
            const uint32_t v = uint_field(s, f);
            if (!partition_name(v)) out << "must be 0 (watershed), 1 (monotone) or 2 (layers) (got " << v << ")";
            break;
        }
        case Kind::Flag: {
            const unsigned v = flag_field(s, f);
            if (v > 1) out << "must be 0 or 1 (got " << v << ")";
            break;
        }
        case Kind::Cells: return cells_problem(f.name, uint_field(s, f));
    }
    return out.str();
}

const char* json_type(const nlohmann::json& v) { return v.type_name(); }

// True if integer JSON value `v` lies in lo..hi (then stored in *out). nlohmann keeps non-negative
// integers as uint64 and negative ones as int64.
bool integer_in(const nlohmann::json& v, int64_t lo, int64_t hi, int64_t* out) {
    if (v.is_number_unsigned()) {
        const uint64_t u = v.get<uint64_t>();
        if (u > static_cast<uint64_t>(hi)) return false;
        *out = static_cast<int64_t>(u);
    } else {
        *out = v.get<int64_t>();
    }
    return *out >= lo && *out <= hi;
}

// Stores JSON value `v` into field `f` of `s`, or fails naming the field.
void apply_json_value(nl_recast_settings& s, const Field& f, const nlohmann::json& v) {
    const std::string where = std::string("settings_json: ") + f.name;
    switch (f.kind) {
        case Kind::Float: {
            if (!v.is_number()) fail(NL_STATUS_INVALID_ARGUMENT, where, " must be a number, not ", json_type(v));
            const double d = v.get<double>();
            const std::string problem = float_problem(f.name, d);
            if (!problem.empty()) fail(NL_STATUS_INVALID_ARGUMENT, where, " ", problem);
            float_field(s, f) = static_cast<float>(d);
            return;
        }
        case Kind::Integer: {
            if (!v.is_number_integer())
                fail(NL_STATUS_INVALID_ARGUMENT, where, " must be an integer, not ", nl::json_excerpt(v));
            int64_t n = 0;
            if (!integer_in(v, 3, 6, &n))
                fail(NL_STATUS_INVALID_ARGUMENT, where, " must be in 3..6 (got ", nl::json_excerpt(v), ")");
            uint_field(s, f) = static_cast<uint32_t>(n);
            return;
        }
        case Kind::Partition: {
            if (v.is_string()) {
                const std::string name = v.get<std::string>();
                for (uint32_t p = 0; partition_name(p); ++p) {
                    if (name == partition_name(p)) {
                        uint_field(s, f) = p;
                        return;
                    }
                }
                fail(NL_STATUS_INVALID_ARGUMENT, where, " must be \"watershed\", \"monotone\" or \"layers\" (got ",
                     nl::json_excerpt(v), ")");
            }
            if (!v.is_number_integer())
                fail(NL_STATUS_INVALID_ARGUMENT, where, " must be a string or an integer, not ", json_type(v));
            int64_t p = 0;
            if (!integer_in(v, 0, 2, &p))
                fail(NL_STATUS_INVALID_ARGUMENT, where, " must be 0 (watershed), 1 (monotone) or 2 (layers) (got ",
                     nl::json_excerpt(v), ")");
            uint_field(s, f) = static_cast<uint32_t>(p);
            return;
        }
        case Kind::Flag:
            if (!v.is_boolean()) fail(NL_STATUS_INVALID_ARGUMENT, where, " must be true or false, not ", json_type(v));
            flag_field(s, f) = v.get<bool>() ? 1 : 0;
            return;
        case Kind::Cells: {
            if (!v.is_number_integer())
                fail(NL_STATUS_INVALID_ARGUMENT, where, " must be an integer, not ", nl::json_excerpt(v));
            int64_t n = 0;
            if (!integer_in(v, 0, kMaxTileCells, &n))
                fail(NL_STATUS_INVALID_ARGUMENT, where, " must be in 0..", kMaxTileCells, " cells (got ",
                     nl::json_excerpt(v), ")");
            const std::string problem = cells_problem(f.name, n);
            if (!problem.empty()) fail(NL_STATUS_INVALID_ARGUMENT, where, " ", problem);
            uint_field(s, f) = static_cast<uint32_t>(n);
            return;
        }
    }
}

void apply_json(nl_recast_settings& s, const char* text, size_t length) {
    nlohmann::json doc;
    try {
        doc = nl::parse_json(std::string_view(text, length), "settings_json");
    } catch (const nl::Error& e) {
        fail(e.code() == nl::ErrorCode::Parse ? NL_STATUS_PARSE_ERROR : NL_STATUS_INVALID_ARGUMENT, e.what());
    }
    if (!doc.is_object()) fail(NL_STATUS_INVALID_ARGUMENT, "settings_json must be a JSON object, not ", json_type(doc));
    for (const auto& [key, value] : doc.items()) {
        const Field* field = nullptr;
        for (const Field& f : kFields) {
            if (key == f.name) field = &f;
        }
        if (!field)
            fail(NL_STATUS_INVALID_ARGUMENT, "settings_json: unknown key ", nl::quoted_excerpt(key),
                 " (known keys: ", known_keys(), ")");
        apply_json_value(s, *field, value);
    }
}

void check_agent_field(const char* name, float v, bool ok, const char* rule) {
    if (!std::isfinite(v) || !ok)
        fail(NL_STATUS_INVALID_ARGUMENT, "agent_type.", name, " must be ", rule, " (got ", v, ")");
}

}  // namespace

void validate_agent(const nl_agent_type& a) {
    check_agent_field("radius", a.radius, a.radius >= 0.0f, "finite and >= 0");
    check_agent_field("height", a.height, a.height > 0.0f, "finite and > 0");
    check_agent_field("max_climb", a.max_climb, a.max_climb >= 0.0f, "finite and >= 0");
    check_agent_field("max_slope", a.max_slope, a.max_slope >= 0.0f && a.max_slope < 90.0f, "in [0, 90) degrees");
}

nl_recast_settings resolve_settings(const nl_navmesh_build_def& def) {
    nl_recast_settings s = default_settings();
    if (def.settings) {
        uint32_t size = 0;
        std::memcpy(&size, def.settings, sizeof size);
        if (size < kFirstSettingsSize)
            fail(NL_STATUS_INVALID_ARGUMENT, "settings.size is ", size, " but an nl_recast_settings has at least ",
                 kFirstSettingsSize, " bytes (fill it from nl_default_recast_settings())");
        // A newer caller's struct may be longer: its extra fields are not known to this builder.
        std::memcpy(&s, def.settings, std::min<size_t>(size, sizeof s));
        s.size = sizeof s;
        for (const Field& f : kFields) {
            const std::string problem = field_problem(s, f);
            if (!problem.empty()) fail(NL_STATUS_INVALID_ARGUMENT, "settings.", f.name, " ", problem);
        }
    }
    if (def.settings_json) {
        apply_json(s, def.settings_json, def.settings_json_length);
    } else if (def.settings_json_length != 0) {
        fail(NL_STATUS_INVALID_ARGUMENT, "settings_json is NULL but settings_json_length is ",
             def.settings_json_length);
    }
    return s;
}

std::string settings_to_json(const nl_recast_settings& settings) {
    nl_recast_settings s = settings;
    nlohmann::json out = nlohmann::json::object();
    for (const Field& f : kFields) {
        switch (f.kind) {
            case Kind::Float: out[f.name] = nl::shortest_decimal(float_field(s, f)); break;
            case Kind::Integer: out[f.name] = uint_field(s, f); break;
            case Kind::Partition: out[f.name] = partition_name(uint_field(s, f)); break;
            case Kind::Flag: out[f.name] = flag_field(s, f) != 0; break;
            case Kind::Cells: out[f.name] = uint_field(s, f); break;
        }
    }
    return out.dump();
}

}  // namespace nl::recast

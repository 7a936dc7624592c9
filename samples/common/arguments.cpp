#include "arguments.h"

#include <cctype>
#include <cmath>
#include <cstdlib>

#include "sample_error.h"

namespace nl::samples {

Arguments::Arguments(const std::string& program, const std::string& command, int argc, char** argv, int first,
                     const std::vector<OptionSpec>& options)
    : command_(command), program_(program) {
    for (int i = first; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--help" || arg == "-h") {
            help_ = true;
            continue;
        }
        if (arg.size() < 2 || arg.compare(0, 2, "--") != 0 || arg == "--") {
            if (!arg.empty() && arg[0] == '-' && arg.size() > 1 && !std::isdigit(static_cast<unsigned char>(arg[1])))
                throw SampleError(command_ + ": unknown option '" + arg + "' (see " + program_ + " --help)");
            positional_.push_back(arg);
            continue;
        }
        const size_t equals = arg.find('=');
        const std::string name = arg.substr(2, equals == std::string::npos ? std::string::npos : equals - 2);
        const OptionSpec* spec = nullptr;
        for (const OptionSpec& o : options)
            if (o.name == name) spec = &o;
        if (!spec) throw SampleError(command_ + ": unknown option '--" + name + "' (see " + program_ + " --help)");
        if (values_.count(name)) throw SampleError(command_ + ": --" + name + " given twice");
        if (!spec->takes_value) {
            if (equals != std::string::npos) throw SampleError(command_ + ": --" + name + " takes no value");
            values_[name] = "";
        } else if (equals != std::string::npos) {
            values_[name] = arg.substr(equals + 1);
        } else {
            if (i + 1 >= argc) throw SampleError(command_ + ": --" + name + " needs a value");
            values_[name] = argv[++i];
        }
        if (spec->takes_value && values_[name].empty()) throw SampleError(command_ + ": --" + name + " needs a value");
    }
}

std::optional<std::string> Arguments::value(const std::string& name) const {
    const auto it = values_.find(name);
    if (it == values_.end()) return std::nullopt;
    return it->second;
}

std::string Arguments::required(const std::string& name) const {
    const auto it = values_.find(name);
    if (it == values_.end()) throw SampleError(command_ + ": --" + name + " is required (see " + program_ + " --help)");
    return it->second;
}

long Arguments::whole_number(const std::string& name, long lo, long hi, long fallback) const {
    const auto it = values_.find(name);
    return it == values_.end() ? fallback : parse_whole_number(it->second, "--" + name, lo, hi);
}

void Arguments::expect_positional(size_t count, const std::string& what) const {
    if (positional_.size() < count)
        throw SampleError(command_ + ": missing " + what + " (see " + program_ + " --help)");
    if (positional_.size() > count)
        throw SampleError(command_ + ": unexpected argument '" + positional_[count] + "' (see " + program_ +
                          " --help)");
}

void parse_point(const std::string& text, const std::string& option, float out[3]) {
    const char* p = text.c_str();
    for (int k = 0; k < 3; ++k) {
        char* end = nullptr;
        const float value = std::strtof(p, &end);
        const char expected = k < 2 ? ',' : '\0';
        if (end == p || *end != expected || !std::isfinite(value))
            throw SampleError(option + " must be three numbers X,Y,Z (got '" + text + "')");
        out[k] = value;
        p = end + 1;
    }
}

long parse_whole_number(const std::string& text, const std::string& option, long lo, long hi) {
    char* end = nullptr;
    const long value = std::strtol(text.c_str(), &end, 10);
    if (text.empty() || *end != '\0' || value < lo || value > hi)
        throw SampleError(option + " must be a whole number from " + std::to_string(lo) + " to " + std::to_string(hi) +
                          " (got '" + text + "')");
    return value;
}

}  // namespace nl::samples

// Command-line arguments of one sample command: positional arguments, options with a value
// ("--out FILE" or "--out=FILE") and flags ("--json"). Anything not declared is refused.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace nl::samples {

struct OptionSpec {
    std::string name;  // without the dashes: "out"
    bool takes_value;  // "--out FILE" vs "--json"
};

class Arguments {
public:
    // Parses argv[first..argc). Throws SampleError ("generate: unknown option '--x' (see navlink generate
    // --help)", "generate: --out needs a value", ...): messages start with `command` and point to
    // `program` --help.
    Arguments(const std::string& program, const std::string& command, int argc, char** argv, int first,
              const std::vector<OptionSpec>& options);

    const std::vector<std::string>& positional() const { return positional_; }
    bool has(const std::string& name) const { return values_.count(name) != 0; }
    std::optional<std::string> value(const std::string& name) const;
    // The value of an option the command cannot do without; throws SampleError if absent.
    std::string required(const std::string& name) const;
    // The value of a whole-number option in [lo, hi], or `fallback` when it is absent; throws
    // SampleError naming the option when it is not a whole number in range.
    long whole_number(const std::string& name, long lo, long hi, long fallback) const;
    // Throws unless there are exactly `count` positional arguments (`what` names them for the message).
    void expect_positional(size_t count, const std::string& what) const;
    bool wants_help() const { return help_; }

private:
    std::string command_;
    std::string program_;
    std::vector<std::string> positional_;
    std::map<std::string, std::string> values_;
    bool help_ = false;
};

// Parses "X,Y,Z" into three finite floats; throws SampleError naming `option` otherwise.
void parse_point(const std::string& text, const std::string& option, float out[3]);

// Parses a whole number in [lo, hi]; throws SampleError naming `option` otherwise.
long parse_whole_number(const std::string& text, const std::string& option, long lo, long hi);

}  // namespace nl::samples

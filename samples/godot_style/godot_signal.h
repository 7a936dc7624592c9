// A Godot-style signal (named so as not to shadow the system <signal.h>): callables connected to it run, in order, when
// it is emitted. Everything runs on the scene tree's thread (results from NavLink's path workers arrive through
// call_deferred).
#pragma once

#include <functional>
#include <utility>
#include <vector>

namespace nl::godot_style {

template <typename... Args>
class Signal {
public:
    void connect(std::function<void(Args...)> callable) { callables_.push_back(std::move(callable)); }
    void emit(Args... args) const {
        for (const auto& c : callables_) c(args...);
    }

private:
    std::vector<std::function<void(Args...)>> callables_;
};

}  // namespace nl::godot_style

// What a call into the core throws, for tests of the core: its nl::Error's code and message.
#pragma once

#include <doctest/doctest.h>

#include <functional>
#include <string>

#include "util/error.h"

namespace nl::test {

// The code of the nl::Error `fn` throws (the test fails when it throws none); its message into
// `message` when given.
inline ErrorCode code_of(const std::function<void()>& fn, std::string* message = nullptr) {
    try {
        fn();
    } catch (const Error& e) {
        if (message) *message = e.what();
        return e.code();
    }
    FAIL("no error");
    return ErrorCode::Internal;
}

// The message of the nl::Error `fn` throws, "" when it throws none.
inline std::string message_of(const std::function<void()>& fn) {
    try {
        fn();
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

}  // namespace nl::test

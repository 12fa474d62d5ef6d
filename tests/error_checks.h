// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// Checks that a library call reports an error, in both builds of the engine: with exceptions
// (MEFF_EXCEPTIONS, the default) the call throws; without (MEFF_EXCEPTIONS=OFF, the unit tier
// built with -fno-exceptions) the error handler (meff::SetErrorHandler) receives the same
// message, once, and the call returns.
#pragma once

#include "meff/error.h"

#include <catch2/catch.hpp>

#include <string>
#include <utility>
#include <vector>

namespace meff::test
{

/// Collects the messages the error handler receives while it lives; the default handler is
/// back afterwards.
class CapturedErrors
{
  public:
    CapturedErrors() { SetErrorHandler(&Record, this); }
    ~CapturedErrors() { SetErrorHandler(nullptr); }
    CapturedErrors(const CapturedErrors&) = delete;
    CapturedErrors& operator=(const CapturedErrors&) = delete;

    std::vector<std::string> messages;

  private:
    static void Record(const char* message, void* context)
    {
        static_cast<CapturedErrors*>(context)->messages.emplace_back(message);
    }
};

/// The message of the InvalidArgument `call` reports (thrown, or handed to the error handler),
/// or "accepted" when it reports none.
template <typename Call>
std::string ErrorMessageOf(Call&& call)
{
#if MEFF_EXCEPTIONS
    try
    {
        std::forward<Call>(call)();
    }
    catch (const InvalidArgument& error)
    {
        return error.what();
    }
    return "accepted";
#else
    const CapturedErrors captured;
    std::forward<Call>(call)();
    CHECK(captured.messages.size() <= 1); // the refused call returned at its first error
    return captured.messages.empty() ? std::string("accepted") : captured.messages.front();
#endif
}

} // namespace meff::test

#if MEFF_EXCEPTIONS
/// `expr` reports an InvalidArgument.
#define MEFF_CHECK_ERROR(expr) CHECK_THROWS_AS(expr, meff::InvalidArgument)
/// `expr` reports an error whose message `matcher` accepts.
#define MEFF_CHECK_ERROR_WITH(expr, matcher) CHECK_THROWS_WITH(expr, matcher)
/// `expr` reports no error.
#define MEFF_CHECK_NO_ERROR(expr) CHECK_NOTHROW(expr)
#else
#define MEFF_CHECK_ERROR(expr)                                                                     \
    CHECK(meff::test::ErrorMessageOf([&] { static_cast<void>(expr); }) != "accepted")
#define MEFF_CHECK_ERROR_WITH(expr, matcher)                                                       \
    CHECK_THAT(meff::test::ErrorMessageOf([&] { static_cast<void>(expr); }), matcher)
#define MEFF_CHECK_NO_ERROR(expr)                                                                  \
    CHECK(meff::test::ErrorMessageOf([&] { static_cast<void>(expr); }) == "accepted")
#endif

// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// A non-owning reference to something callable, for callbacks that must not allocate: unlike
// std::function it never copies the callable or allocates, it only points at it. The callable
// must outlive the FunctionRef — passing a lambda straight to a function taking a FunctionRef
// is the intended use (the lambda lives until the call returns).
#pragma once

#include <functional>
#include <memory>
#include <type_traits>
#include <utility>

namespace meff
{

template <typename Signature>
class FunctionRef;

/// A non-owning reference to a callable (R(Args...)): what the world's queries and the task
/// system take, without allocating. The callable must outlive the call it is passed to.
template <typename R, typename... Args>
class FunctionRef<R(Args...)>
{
  public:
    /// Refers to `callable` (a lambda converts implicitly).
    template <typename F>
    requires(!std::is_same_v<std::remove_cvref_t<F>, FunctionRef> &&
             std::is_invocable_r_v<R, F&, Args...>) FunctionRef(F&& callable)
    noexcept // NOLINT(google-explicit-constructor): a lambda converts
        : m_object(const_cast<void*>(static_cast<const void*>(std::addressof(callable)))),
          m_call(&Call<std::remove_reference_t<F>>)
    {
    }

    /// Calls the callable.
    R operator()(Args... args) const { return m_call(m_object, std::forward<Args>(args)...); }

  private:
    template <typename F>
    static R Call(void* object, Args... args)
    {
        return std::invoke(*static_cast<F*>(object), std::forward<Args>(args)...);
    }

    void* m_object;
    R (*m_call)(void*, Args...);
};

} // namespace meff

// nl::HeldPtr<T>: a std::shared_ptr returned by value whose pointee cannot be reached through the
// temporary itself. `for (const X& x : *registry.links(h))` and `const X& r = registry.navmesh(h)->polygons();`
// compile with a plain shared_ptr and read freed memory as soon as another thread publishes the next
// snapshot: the temporary owner dies at the end of the full expression (C++17 does not extend its life
// in a range-for), and only the registry's own copy kept the object alive until then. With a HeldPtr
// `*`, `->` and get() on a temporary fail to compile: name the owner first
// (`const auto links = registry.links(h);`), which also keeps every read of it on one snapshot.
#pragma once

#include <memory>
#include <utility>

namespace nl {

template <typename T>
class HeldPtr : public std::shared_ptr<T> {
public:
    HeldPtr() = default;
    template <typename U>
    HeldPtr(std::shared_ptr<U> owner) noexcept : std::shared_ptr<T>(std::move(owner)) {}  // NOLINT: implicit on purpose

    T& operator*() const& noexcept { return std::shared_ptr<T>::operator*(); }
    T* operator->() const& noexcept { return std::shared_ptr<T>::get(); }
    T* get() const& noexcept { return std::shared_ptr<T>::get(); }
    // The owner is a temporary: hold it in a variable first.
    T& operator*() const&& = delete;
    T* operator->() const&& = delete;
    T* get() const&& = delete;
};

}  // namespace nl

// Copy-on-write values and vectors: copies share one value until one of them changes it.
#pragma once

#include <cstddef>
#include <initializer_list>
#include <memory>
#include <utility>
#include <vector>

namespace wardray::scene {

/// A T held behind a shared pointer: copying is O(1), both copies share the value, and the first change through a
/// non-const access gives the changed copy a value of its own. Empty means a default T (allocated on first change),
/// so a default Cow costs one pointer. Compared by value.
template <typename T>
class Cow {
public:
    Cow() = default;
    Cow(const T& value) : m_value(std::make_shared<T>(value)) {}
    Cow(T&& value) : m_value(std::make_shared<T>(std::move(value))) {}
    Cow& operator=(const T& value) { return *this = Cow(value); }
    Cow& operator=(T&& value) { return *this = Cow(std::move(value)); }

    const T& get() const { return m_value ? *m_value : default_value(); }
    operator const T&() const { return get(); }
    const T& operator*() const { return get(); }
    const T* operator->() const { return &get(); }
    /// The value to change: this Cow's own (copied first while shared).
    T& mut() {
        if (!m_value) m_value = std::make_shared<T>();
        else if (m_value.use_count() > 1) m_value = std::make_shared<T>(*m_value);
        return *m_value;
    }
    T& operator*() { return mut(); }
    T* operator->() { return &mut(); }

    /// True when both hold the very same value (a copy not changed since).
    bool shares(const Cow& other) const { return m_value == other.m_value; }
    /// True when this Cow holds a value no other copy shares, so a change needs no copy.
    bool unique() const { return m_value && m_value.use_count() == 1; }
    bool operator==(const Cow& other) const { return m_value == other.m_value || get() == other.get(); }

private:
    static const T& default_value() {
        static const T value{};
        return value;
    }
    std::shared_ptr<T> m_value;
};

/// A std::vector shared between copies until one of them changes it: reading through a const one is a const
/// std::vector's interface; a non-const access (operator[], begin, push_back, ...) copies a shared vector first.
template <typename T>
class SharedVector {
public:
    using value_type = T;
    using size_type = std::size_t;
    using iterator = typename std::vector<T>::iterator;
    using const_iterator = typename std::vector<T>::const_iterator;

    SharedVector() = default;
    SharedVector(std::vector<T> v) : m_data(std::move(v)) {}
    SharedVector(std::initializer_list<T> list) : m_data(std::vector<T>(list)) {}

    const std::vector<T>& get() const { return *m_data; }
    operator const std::vector<T>&() const { return get(); }
    /// The vector to change: this one's own (copied first while shared).
    std::vector<T>& mut() { return m_data.mut(); }
    /// True when both hold the very same elements (a copy not changed since).
    bool shares(const SharedVector& other) const { return m_data.shares(other.m_data); }
    /// True when no other copy shares these elements, so a change needs no copy.
    bool unique() const { return m_data.unique(); }
    /// The address of the elements, the same for copies that share them.
    const T* data() const { return get().data(); }

    std::size_t size() const { return get().size(); }
    bool empty() const { return get().empty(); }
    const T& operator[](std::size_t i) const { return get()[i]; }
    const T& at(std::size_t i) const { return get().at(i); }
    const T& front() const { return get().front(); }
    const T& back() const { return get().back(); }
    const_iterator begin() const { return get().begin(); }
    const_iterator end() const { return get().end(); }
    const_iterator cbegin() const { return get().begin(); }
    const_iterator cend() const { return get().end(); }

    T& operator[](std::size_t i) { return mut()[i]; }
    T& front() { return mut().front(); }
    T& back() { return mut().back(); }
    iterator begin() { return mut().begin(); }
    iterator end() { return mut().end(); }
    void push_back(const T& v) { mut().push_back(v); }
    void push_back(T&& v) { mut().push_back(std::move(v)); }
    template <typename... A>
    T& emplace_back(A&&... a) { return mut().emplace_back(std::forward<A>(a)...); }
    void reserve(std::size_t n) { mut().reserve(n); }
    void resize(std::size_t n) { mut().resize(n); }
    void resize(std::size_t n, const T& v) { mut().resize(n, v); }
    void clear() { m_data = Cow<std::vector<T>>(); }

    bool operator==(const SharedVector& other) const { return m_data == other.m_data; }

private:
    Cow<std::vector<T>> m_data;
};

}  // namespace wardray::scene

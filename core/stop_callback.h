// StopCallback: a reference to a callable that takes one value and returns whether to stop (a search handing out
// what it finds one at a time).
#pragma once

#include <type_traits>

namespace wardray {

/// Refers to a callable `bool(Arg)` without owning it (it must outlive the call it is passed to), so that a search
/// compiled once can hand its finds to any caller's lambda, which returns true to end the search.
template <typename Arg>
class StopCallback {
public:
    template <typename F>
        requires(!std::is_same_v<std::remove_cv_t<F>, StopCallback>)
    StopCallback(F& f)
        : m_object(&f), m_call([](void* o, Arg a) { return static_cast<bool>((*static_cast<F*>(o))(a)); }) {}
    bool operator()(Arg a) const { return m_call(m_object, a); }

private:
    void* m_object;
    bool (*m_call)(void*, Arg);
};

}  // namespace wardray

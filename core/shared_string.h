// SharedString: an immutable string whose copies share one allocation (file paths held by every source location).
#pragma once

#include <memory>
#include <ostream>
#include <string>
#include <string_view>

namespace wardray {

/// A string that never changes once made: copying it copies a pointer, so the many copies of one file's path (a
/// location in every object, pigment and finish of a scene) cost one allocation between them. Reads as a const
/// std::string.
class SharedString {
public:
    SharedString() = default;
    SharedString(std::string s) : m_text(s.empty() ? nullptr : std::make_shared<const std::string>(std::move(s))) {}
    SharedString(const char* s) : SharedString(std::string(s)) {}
    SharedString(std::string_view s) : SharedString(std::string(s)) {}

    const std::string& str() const { return m_text ? *m_text : empty_string(); }
    operator const std::string&() const { return str(); }
    operator std::string_view() const { return str(); }
    bool empty() const { return str().empty(); }
    std::size_t size() const { return str().size(); }
    const char* c_str() const { return str().c_str(); }

    bool operator==(const SharedString& other) const { return m_text == other.m_text || str() == other.str(); }
    bool operator==(const std::string& other) const { return str() == other; }
    bool operator==(const char* other) const { return str() == other; }
    friend std::ostream& operator<<(std::ostream& out, const SharedString& s) { return out << s.str(); }
    friend std::string operator+(const SharedString& a, const std::string& b) { return a.str() + b; }
    friend std::string operator+(const std::string& a, const SharedString& b) { return a + b.str(); }
    friend std::string operator+(const SharedString& a, const char* b) { return a.str() + b; }
    friend std::string operator+(const char* a, const SharedString& b) { return a + b.str(); }
    friend std::string operator+(const SharedString& a, char b) { return a.str() + b; }

private:
    static const std::string& empty_string() {
        static const std::string empty;
        return empty;
    }
    std::shared_ptr<const std::string> m_text;
};

}  // namespace wardray

// The parse's budgets: objects created and memory taken, each an error at the statement that crosses it.
#include <cstdio>
#include <unistd.h>

#include "parser/source_stream.h"

namespace wardray::parser {

std::size_t resident_bytes() {
    std::FILE* f = std::fopen("/proc/self/statm", "r");
    if (f == nullptr) return 0;
    unsigned long size = 0;
    unsigned long resident = 0;
    const int n = std::fscanf(f, "%lu %lu", &size, &resident);
    std::fclose(f);
    const long page = sysconf(_SC_PAGESIZE);
    return n == 2 && page > 0 ? static_cast<std::size_t>(resident) * static_cast<std::size_t>(page) : 0;
}

void SourceStream::count_objects(const Token& at, std::size_t n) {
    m_objects_created += n;
    if (m_objects_created <= m_options.max_objects) return;
    report(make_diagnostic(Severity::Error, at,
                           "the scene created more than the limit of " + std::to_string(m_options.max_objects) +
                               " objects (an endless loop making objects?); raise it with --max-objects"));
    throw FatalError{};
}

void SourceStream::count_copies(const Token& at, std::size_t n) {
    constexpr std::size_t k_copies_per_object = 10;
    m_objects_copied += n;
    if (m_objects_copied / k_copies_per_object > m_options.max_objects) {
        report(make_diagnostic(Severity::Error, at,
                               "the scene copied more than the limit of " +
                                   std::to_string(m_options.max_objects * k_copies_per_object) +
                                   " objects (a loop copying a growing object?); raise it with --max-objects"));
        throw FatalError{};
    }
    count_objects(at, n);
}

void SourceStream::check_memory(const Token& at, std::size_t about_to_take) {
    const std::size_t now = resident_bytes() + about_to_take;
    if (now <= m_resident_at_start || now - m_resident_at_start <= m_options.max_memory_bytes) return;
    report(make_diagnostic(Severity::Error, at,
                           "the parse took more than the limit of " +
                               std::to_string(m_options.max_memory_bytes >> 20) +
                               " MB of memory (an endless loop?); raise it with --max-memory MB"));
    throw FatalError{};
}

}  // namespace wardray::parser

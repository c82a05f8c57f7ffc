// Read confinement, binary-file detection and source-text normalization (BOM, line ends) for every file read.
#include "parser/read_access.h"

#include <cstdio>
#include <system_error>

namespace wardray::parser {

namespace {

namespace fs = std::filesystem;

// The real location of a path (symbolic links and '..' resolved, as far as it exists).
fs::path real_path(const fs::path& p) {
    std::error_code ec;
    const fs::path absolute = fs::absolute(p, ec);
    if (ec) return p.lexically_normal();
    fs::path r = fs::weakly_canonical(absolute, ec);
    return ec ? absolute.lexically_normal() : r;
}

bool inside(const fs::path& file, const fs::path& folder) {
    auto fi = file.begin();
    for (auto di = folder.begin(); di != folder.end(); ++di, ++fi) {
        if (di->empty()) continue;  // a trailing separator
        if (fi == file.end() || *fi != *di) return false;
    }
    return true;
}

// Length of the valid UTF-8 sequence starting at s[i] (2 to 4), or 0.
std::size_t utf8_sequence(std::string_view s, std::size_t i) {
    const auto c = static_cast<unsigned char>(s[i]);
    const std::size_t n = c >= 0xF0 && c <= 0xF4 ? 4 : c >= 0xE0 ? 3 : c >= 0xC2 && c < 0xE0 ? 2 : 0;
    if (n == 0 || i + n > s.size()) return 0;
    for (std::size_t k = 1; k < n; ++k)
        if ((static_cast<unsigned char>(s[i + k]) & 0xC0) != 0x80) return 0;
    return n;
}

bool plain_byte(unsigned char c) { return (c >= 0x20 && c < 0x7F) || c == '\t'; }

void escape_byte(std::string& out, unsigned char c) {
    char buf[8];
    std::snprintf(buf, sizeof buf, "\\x%02X", c);
    out += buf;
}

}  // namespace

std::vector<ReadRoot> readable_roots(const ParseOptions& options, const fs::path& scene_file) {
    std::vector<ReadRoot> roots;
    const fs::path folder = scene_file.parent_path();
    roots.push_back({folder.empty() ? fs::path(".") : folder, false});
    for (const auto& p : options.library_paths) roots.push_back({p, true});
    for (const auto& p : options.read_paths) roots.push_back({p, true});
    for (const auto& p : options.permitted_reads) roots.push_back({p.folder, false, p.subfolders});
    return roots;
}

bool is_readable(const fs::path& file, const std::vector<ReadRoot>& roots) {
    const fs::path real = real_path(file);
    std::error_code ec;
    const fs::path written = fs::absolute(file, ec).lexically_normal();
    for (const ReadRoot& root : roots) {
        if (!root.subfolders) {
            fs::path folder = real_path(root.folder);
            if (!folder.has_filename()) folder = folder.parent_path();  // "/tmp/" as "/tmp"
            if (real.parent_path() == folder) return true;
            continue;
        }
        if (inside(real, real_path(root.folder))) return true;
        if (root.trusted && !ec && inside(written, fs::absolute(root.folder, ec).lexically_normal())) return true;
    }
    return false;
}

std::string read_refusal(const fs::path& file, std::string_view what) {
    return "reading '" + real_path(file).string() + "' (" + std::string(what) +
           ") is not allowed: files are read only from the scene's folder, the include path (+L, Library_Path) and "
           "the folders given with --read-path DIR";
}

std::optional<std::string> binary_excerpt(std::string_view text) {
    const std::string_view sample = text.substr(0, 4096);
    bool binary = sample.starts_with("\xFF\xFE") || sample.starts_with("\xFE\xFF") ||
                  sample.find('\0') != std::string_view::npos;
    if (!binary && !sample.empty()) {
        std::size_t odd = 0;
        for (std::size_t i = 0; i < sample.size(); ++i) {
            const auto c = static_cast<unsigned char>(sample[i]);
            if (c >= 0x80) {
                const std::size_t n = utf8_sequence(sample, i);
                if (n == 0) ++odd;
                else i += n - 1;
            } else if (c < 0x20 && c != '\t' && c != '\n' && c != '\r' && c != '\f' && c != '\v' && c != 0x1A) {
                ++odd;
            }
        }
        binary = odd * 4 > sample.size();
    }
    if (!binary) return std::nullopt;
    std::string out;
    for (std::size_t i = 0; i < sample.size() && i < 16; ++i) {
        const auto c = static_cast<unsigned char>(sample[i]);
        if (plain_byte(c) && c != '\\' && c != '"' && c != '\t') out += static_cast<char>(c);
        else escape_byte(out, c);
    }
    if (text.size() > 16) out += "...";
    return out;
}

void normalize_source_text(std::string& text) {
    if (text.starts_with("\xEF\xBB\xBF")) text.erase(0, 3);
    if (text.find('\r') == std::string::npos) return;
    std::string out;
    out.reserve(text.size());
    for (std::size_t i = 0; i < text.size(); ++i) {
        if (text[i] != '\r') {
            out += text[i];
            continue;
        }
        out += '\n';
        if (i + 1 < text.size() && text[i + 1] == '\n') ++i;
    }
    text = std::move(out);
}

std::string printable_source_line(std::string_view line, std::size_t max_chars) {
    bool plain = line.size() <= max_chars;
    for (std::size_t i = 0; plain && i < line.size(); ++i) {
        const auto c = static_cast<unsigned char>(line[i]);
        if (c >= 0x80) {
            const std::size_t n = utf8_sequence(line, i);
            if (n == 0) plain = false;
            else i += n - 1;
        } else if (!plain_byte(c)) {
            plain = false;
        }
    }
    if (plain) return std::string(line);
    std::string out;
    for (std::size_t i = 0; i < line.size() && out.size() < max_chars; ++i) {
        const auto c = static_cast<unsigned char>(line[i]);
        const std::size_t n = c >= 0x80 ? utf8_sequence(line, i) : 0;
        if (n > 0) {
            out.append(line.substr(i, n));
            i += n - 1;
        } else if (plain_byte(c)) {
            out += static_cast<char>(c);
        } else {
            escape_byte(out, c);
        }
    }
    if (out.size() >= max_chars) out += "...";
    return out;
}

}  // namespace wardray::parser

// #fopen, #read, #write and #fclose, with file access confined to the folders the parse options allow.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "parser/parser.h"

namespace wardray::parser {

/// An open data file: a reader holds the tokens of the whole file, a writer an output stream.
struct OpenFile {
    std::string path;
    bool writing = false;
    std::string text;  ///< a reader's whole file, which its tokens view
    DecodedStrings decoded;
    std::vector<Token> tokens;
    std::size_t pos = 0;
    std::ofstream out;
    std::ostringstream memory;  ///< where writes go while writing files is off
    bool in_memory = false;
    std::string key;  ///< the resolved path, naming the in-memory copy

    std::ostream& sink() { return in_memory ? static_cast<std::ostream&>(memory) : out; }
};

namespace {

namespace fs = std::filesystem;

// The real location of a path (symbolic links and '..' resolved, as far as it exists).
fs::path resolved(const fs::path& p) {
    std::error_code ec;
    fs::path r = fs::weakly_canonical(fs::absolute(p, ec), ec);
    return ec ? fs::absolute(p).lexically_normal() : r;
}

bool is_within(const fs::path& file, const fs::path& folder) {
    const fs::path f = resolved(file);
    const fs::path d = resolved(folder);
    auto fi = f.begin();
    for (auto di = d.begin(); di != d.end(); ++di, ++fi) {
        if (di->empty()) continue;  // a trailing separator
        if (fi == f.end() || *fi != *di) return false;
    }
    return true;
}

// POV-Ray's #write of a float: as %g would print it.
std::string format_number(double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
}

void write_binary(std::ostream& out, const std::string& type, double value) {
    const bool is_signed = type[0] == 's';
    const int bits = type.find("32") != std::string::npos ? 32 : type.find("16") != std::string::npos ? 16 : 8;
    const bool big_endian = type.size() > 2 && type.substr(type.size() - 2) == "be";
    const double lo = is_signed ? -std::ldexp(1.0, bits - 1) : 0.0;
    const double hi = is_signed ? std::ldexp(1.0, bits - 1) - 1.0 : std::ldexp(1.0, bits) - 1.0;
    // Rounded to the nearest integer in the representable range, then two's complement.
    const double clamped = std::min(hi, std::max(lo, std::round(value)));
    const auto word = static_cast<std::uint32_t>(static_cast<std::int64_t>(clamped));
    const int bytes = bits / 8;
    for (int i = 0; i < bytes; ++i) {
        const int shift = big_endian ? 8 * (bytes - 1 - i) : 8 * i;
        out.put(static_cast<char>((word >> shift) & 0xFFu));
    }
}

}  // namespace

void Preprocessor::assign_existing_or_global(const std::string& name, Value v) {
    if (Value* existing = lookup_mutable(name)) {
        *existing = std::move(v);
        return;
    }
    declare(name, std::move(v), false);
}

fs::path Preprocessor::scene_relative(const fs::path& requested) const {
    return requested.is_absolute() ? requested : fs::path(m_files.front()->path.str()).parent_path() / requested;
}

void Preprocessor::require_writable(const Token& at, const fs::path& target) {
    const fs::path scene_folder = fs::path(m_files.front()->path.str()).parent_path();
    bool allowed = is_within(target, scene_folder.empty() ? "." : scene_folder);
    for (const auto& p : m_options.write_paths) allowed = allowed || is_within(target, p);
    if (!allowed)
        fail(at, "writing '" + resolved(target).string() +
                     "' is not allowed: files are written only inside the scene's folder and the folders given as "
                     "write paths (--write-path DIR)");
}

void Preprocessor::directive_file_io(const Token& tok) {
    const TokenText& name = tok.text;
    const fs::path scene_folder = fs::path(m_files.front()->path.str()).parent_path();
    if (name == "fopen") {
        const Token id = expect_identifier();
        const Token name_tok = peek();
        const std::string file_name = parse_string();
        const Token mode = expect_identifier();
        if (mode.text != "read" && mode.text != "write" && mode.text != "append")
            fail(mode, "expected read, write or append after the file name but found '" + mode.text + "'");
        auto file = std::make_shared<OpenFile>();
        const fs::path requested(file_name);
        if (mode.text == "read") {
            // Reading: the scene's folder, the include path and the folders the user allowed, in that order.
            std::vector<fs::path> roots{scene_folder.empty() ? fs::path(".") : scene_folder};
            for (const auto& p : m_options.library_paths) roots.push_back(p);
            for (const auto& p : m_options.read_paths) roots.push_back(p);
            std::optional<fs::path> found;
            std::error_code ec;
            // A file this parse wrote while writing is off reads back from memory.
            const auto memory = m_memory_files.find(
                resolved(requested.is_absolute() ? requested : (scene_folder / requested)).string());
            if (memory != m_memory_files.end()) {
                std::vector<Diagnostic> errors;
                file->path = file_name;
                file->text = memory->second;
                file->tokens = lex(file->text, 0, file->path, errors, file->decoded);
                declare(id.text, FileHandle{std::move(file)}, false);
                return;
            }
            if (requested.is_absolute()) {
                if (fs::is_regular_file(requested, ec)) found = requested;
            } else {
                for (const auto& r : roots) {
                    if (!fs::is_regular_file(r / requested, ec)) continue;
                    found = r / requested;
                    break;
                }
            }
            if (!found) fail(name_tok, "cannot open '" + file_name + "' for reading: no such file");
            require_readable(name_tok, *found, "#fopen read");
            std::string reason;
            if (!read_text_file(*found, file->text, reason))
                fail(name_tok, "cannot open '" + found->string() + "' for reading: " + reason);
            if (const auto excerpt = binary_excerpt(file->text))
                fail(name_tok, "'" + found->string() + "' is not a text file (it starts with \"" + *excerpt + "\")");
            normalize_source_text(file->text);
            std::vector<Diagnostic> errors;
            file->path = found->string();
            file->tokens = lex(file->text, 0, file->path, errors, file->decoded);
            for (const Diagnostic& e : errors)
                if (e.severity == Severity::Error)
                    fail(name_tok, "'" + file->path + "' is not a valid data file: " + e.message);
        } else {
            // Writing: only inside the scene's folder (or the folders the user allowed).
            const fs::path target = requested.is_absolute() ? requested : (scene_folder / requested);
            using Writes = ParseOptions::FileWrites;
            if (m_options.file_writes == Writes::Refuse)
                fail(name_tok, "writing '" + resolved(target).string() + "' is not allowed: writing files is off");
            require_writable(name_tok, target);
            file->writing = true;
            file->path = target.string();
            if (m_options.file_writes == Writes::Discard) {
                // Written to memory only, so the scene can read it back and nothing on disk changes.
                file->in_memory = true;
                file->key = resolved(target).string();
                if (mode.text == "append") file->memory << m_memory_files[file->key];
                if (m_warned_features.insert("#fopen write discarded").second)
                    warn(name_tok, "'" + file_name + "' is not written: writing files is off (--allow-file-writes "
                                                     "turns it on)");
            } else {
                file->out.open(target, mode.text == "append" ? std::ios::binary | std::ios::app
                                                             : std::ios::binary | std::ios::trunc);
                if (!file->out) fail(name_tok, "cannot open '" + file->path + "' for writing");
            }
        }
        // POV-Ray compat: the handle is always global.
        declare(id.text, FileHandle{std::move(file)}, false);
        return;
    }

    // The other directives name an open handle.
    const bool parenthesised = name != "fclose";
    if (parenthesised) expect("(");
    const Token id = expect_identifier();
    const Value* v = lookup(id.text);
    const auto* handle = v ? std::get_if<FileHandle>(v) : nullptr;
    if (handle == nullptr && name == "fclose") {
        // POV-Ray compat: closing a file that reached its end (and so was closed already) is fine.
        if (v == nullptr) return;
    }
    if (v == nullptr) fail(id, "'" + id.text + "' is not an open file (it was never opened or was closed)");
    if (handle == nullptr) fail(id, "'" + id.text + "' is " + std::string(value_kind_name(*v)) + ", not a file");
    const std::shared_ptr<OpenFile> file = handle->file;
    auto erase_handle = [&] {
        for (auto& scope : m_scopes) scope.erase(id.text);
    };
    if (name == "fclose") {
        // An in-memory file becomes readable once closed (copying it on every #write would be quadratic).
        if (file->in_memory) m_memory_files[file->key] = file->memory.str();
        file->out.close();
        erase_handle();
        return;
    }
    if (name == "write") {
        if (!file->writing) fail(id, "'" + id.text + "' was opened for reading; #write needs write or append");
        // POV-Ray compat: the comma after the handle is optional (portfolio/html_gen.inc leaves it out).
        while (true) {
            accept(",");
            if (is_punct(peek(), ")")) break;
            const Token& t = peek();
            static const char* const binary_types[] = {"uint8",    "sint8",    "uint16be", "uint16le",
                                                       "sint16be", "sint16le", "sint32be", "sint32le"};
            std::string binary;
            for (const char* b : binary_types)
                if (is_word(t, b)) binary = b;
            if (!binary.empty()) {
                next();
                // Binary words up to the next comma; further items after a comma are text again.
                do {
                    const Numeric n = parse_numeric();
                    for (int i = 0; i < n.n; ++i) write_binary(file->sink(), binary, n.v[i]);
                } while (!is_punct(peek(), ",") && !is_punct(peek(), ")"));
                continue;
            }
            std::ostream& sink = file->sink();
            if (starts_string(t)) {
                sink << parse_string();
                continue;
            }
            const Numeric n = parse_numeric();
            if (n.n == 1) {
                sink << format_number(n.v[0]);
            } else {
                sink << '<';
                for (int i = 0; i < n.n; ++i) sink << (i ? "," : "") << format_number(n.v[i]);
                sink << '>';
            }
        }
        expect(")");
        if (!file->in_memory) file->out.flush();
        // A file kept in memory while writing is off must not grow without bound (an endless #write loop).
        if (file->in_memory && static_cast<std::size_t>(file->memory.tellp()) > m_options.max_memory_file_bytes) {
            report(make_diagnostic(Severity::Error, tok,
                                   "'" + file->path + "' grew past " + std::to_string(m_options.max_memory_file_bytes) +
                                       " bytes; files written while writing is off are kept in memory up "
                                       "to that limit; raise it with --max-memory-file"));
            throw FatalError{};
        }
        return;
    }
    // #read: one data item per identifier; past the end the file closes and the handle disappears.
    if (file->writing) fail(id, "'" + id.text + "' was opened for writing; #read needs a file opened with read");
    while (true) {
        accept(",");
        if (is_punct(peek(), ")")) break;
        const Token target = expect_identifier();
        auto& toks = file->tokens;
        auto at = [&]() -> const Token& { return toks[std::min(file->pos, toks.size() - 1)]; };
        if (at().kind == TokenKind::Punct && at().text == ",") ++file->pos;
        if (at().kind == TokenKind::EndOfFile) {
            erase_handle();
            while (!is_punct(peek(), ")")) {
                accept(",");
                if (!is_punct(peek(), ")")) expect_identifier();
            }
            break;
        }
        auto read_float = [&]() -> double {
            double sign = 1.0;
            while (at().kind == TokenKind::Punct && (at().text == "-" || at().text == "+")) {
                if (at().text == "-") sign = -sign;
                ++file->pos;
            }
            if (at().kind != TokenKind::Number)
                fail(target, "'" + file->path + "' line " + std::to_string(at().line) +
                                 ": expected a number, a vector or a string but found " + describe_token(at()));
            return sign * toks[file->pos++].number();
        };
        Value value;
        if (at().kind == TokenKind::String) {
            value = toks[file->pos++].text;
        } else if (at().kind == TokenKind::Punct && at().text == "<") {
            ++file->pos;
            Numeric n;
            n.n = 0;
            while (!(at().kind == TokenKind::Punct && at().text == ">")) {
                if (n.n == 5) fail(target, "'" + file->path + "': a vector has at most 5 components");
                n.v[n.n++] = read_float();
                if (at().kind == TokenKind::Punct && at().text == ",") ++file->pos;
            }
            ++file->pos;
            if (n.n < 2) fail(target, "'" + file->path + "': a vector needs at least 2 components");
            value = n;
        } else {
            value = Numeric::scalar(read_float());
        }
        if (const Value* old = lookup(target.text)) {
            const bool old_string = std::holds_alternative<std::string>(*old);
            const bool new_string = std::holds_alternative<std::string>(value);
            if (!old_string && !std::holds_alternative<Numeric>(*old))
                fail(target, "#read cannot store into '" + target.text + "', which is " + value_kind_name(*old));
            if (old_string != new_string)
                fail(target, "#read found " + std::string(new_string ? "a string" : "a number") + " for '" +
                                 target.text + "', which holds " + value_kind_name(*old));
        }
        assign_existing_or_global(target.text, std::move(value));
    }
    expect(")");
}

}  // namespace wardray::parser

// Tests of #fopen/#read/#write/#fclose and of the folders file access is confined to.
#include <filesystem>
#include <fstream>
#include <sstream>

#include "tests/parser/test_util.h"

namespace wardray::parser {
namespace {

namespace fs = std::filesystem;

/// A fresh folder holding a scene, removed afterwards.
class FileIo : public ::testing::Test {
protected:
    void SetUp() override {
        m_dir = fs::temp_directory_path() /
                ("wardray_fileio_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
        fs::remove_all(m_dir);
        fs::create_directories(m_dir / "scenes");
    }
    void TearDown() override { fs::remove_all(m_dir); }

    void write(const fs::path& p, const std::string& text) { std::ofstream(p) << text; }
    std::string read(const fs::path& p) {
        std::ifstream in(p);
        std::ostringstream ss;
        ss << in.rdbuf();
        return ss.str();
    }
    static ParseOptions writing() {
        ParseOptions o = test::default_options();
        o.file_writes = ParseOptions::FileWrites::Allow;
        return o;
    }
    ParseResult parse(const std::string& scene, ParseOptions o = writing()) {
        write(m_dir / "scenes" / "s.pov", "global_settings { assumed_gamma 1 }\n" + scene);
        return parse_file(m_dir / "scenes" / "s.pov", o);
    }

    fs::path m_dir;
};

TEST_F(FileIo, WriteThenReadBack) {
    const ParseResult w = parse(
        "#fopen Out \"data.txt\" write\n"
        "#write (Out, \"\\\"hello\\\",\", 1.5, \",\", <1, -2, 3>, \"\\n\")\n"
        "#fclose Out\n"
        "#ifdef (Out) #error \"still open\" #end\n");
    ASSERT_TRUE(w.ok()) << test::all_diagnostics(w);
    EXPECT_EQ(read(m_dir / "scenes" / "data.txt"), "\"hello\",1.5,<1,-2,3>\n");

    const ParseResult r = parse(
        "#fopen In \"data.txt\" read\n"
        "#read (In, S, F, V)\n"
        "#if (S != \"hello\" | F != 1.5 | V.y != -2) #error \"wrong values\" #end\n"
        "#read (In, Extra)\n"
        "#if (defined(In)) #error \"In should be gone at the end of the file\" #end\n"
        "#ifdef (Extra) #error \"nothing to read\" #end\n"
        "sphere { V, F }\n");
    ASSERT_TRUE(r.ok()) << test::all_diagnostics(r);
    ASSERT_EQ(r.scene->objects.size(), 1u);
}

TEST_F(FileIo, ReadLoopUntilEndOfFile) {
    write(m_dir / "scenes" / "n.txt", "1, 2,\n -3, 4e1\n");
    const ParseResult r = parse(
        "#declare Sum = 0;\n#fopen In \"n.txt\" read\n"
        "#while (defined(In))\n  #read (In, N)\n  #if (defined(In)) #declare Sum = Sum + N; #end\n#end\n"
        "#if (Sum != 40) #error concat(\"Sum is \", str(Sum, 0, 1)) #end\n");
    EXPECT_TRUE(r.ok()) << test::all_diagnostics(r);
}

TEST_F(FileIo, AppendAddsToTheEnd) {
    write(m_dir / "scenes" / "log.txt", "a");
    const ParseResult r = parse("#fopen L \"log.txt\" append\n#write (L, \"b\", 2)\n#fclose L\n");
    ASSERT_TRUE(r.ok()) << test::all_diagnostics(r);
    EXPECT_EQ(read(m_dir / "scenes" / "log.txt"), "ab2");
}

TEST_F(FileIo, ReadingOutsideTheAllowedFoldersIsRefused) {
    write(m_dir / "secret.txt", "1");
    const ParseResult r = parse("#fopen In \"../secret.txt\" read\n");
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.diagnostics[0].loc.line, 2u);
    EXPECT_EQ(r.diagnostics[0].message,
              "reading '" + (m_dir / "secret.txt").string() +
                  "' (#fopen read) is not allowed: files are read only from the scene's folder, the include path "
                  "(+L, Library_Path) and the folders given with --read-path DIR");
    // A folder the user names is allowed.
    ParseOptions o = writing();
    o.read_paths.push_back(m_dir);
    EXPECT_TRUE(parse("#fopen In \"../secret.txt\" read\n#read (In, A)\n", o).ok());
}

TEST_F(FileIo, WritingOutsideTheSceneFolderIsRefused) {
    ParseResult r = parse("#fopen Out \"../escape.txt\" write\n");
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.diagnostics[0].message, "writing '" + (m_dir / "escape.txt").string() +
                                            "' is not allowed: files are written only inside the scene's folder "
                                            "and the folders given as write paths (--write-path DIR)");
    EXPECT_FALSE(fs::exists(m_dir / "escape.txt"));
    r = parse("#fopen Out \"/tmp/wardray_escape.txt\" write\n");
    EXPECT_FALSE(r.ok());
    ParseOptions o = writing();
    o.file_writes = ParseOptions::FileWrites::Refuse;
    r = parse("#fopen Out \"inside.txt\" write\n", o);
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.diagnostics[0].message.find("writing files is off"), std::string::npos);
}

TEST_F(FileIo, ByDefaultWritesAreParsedButDiscarded) {
    const ParseResult r = parse("#fopen Out \"data.txt\" write\n#write (Out, \"x\", 1)\n#write (Out \"no comma\")\n"
                                "#fclose Out\n",
                                test::default_options());
    ASSERT_TRUE(r.ok()) << test::all_diagnostics(r);
    EXPECT_FALSE(fs::exists(m_dir / "scenes" / "data.txt"));
    ASSERT_FALSE(r.scene->warnings.empty());
    EXPECT_EQ(r.scene->warnings[0].message,
              "'data.txt' is not written: writing files is off (--allow-file-writes turns it on)");
    EXPECT_EQ(r.scene->warnings[0].loc.line, 2u);
    // What was "written" reads back within the same parse.
    const ParseResult back = parse("#fopen Out \"d.txt\" write\n#write (Out, \"\\\"s\\\", 7\")\n#fclose Out\n"
                                   "#fopen In \"d.txt\" read\n#read (In, S, N)\n"
                                   "#if (N != 7 | S != \"s\") #error \"not read back\" #end\n",
                                   test::default_options());
    EXPECT_TRUE(back.ok()) << test::all_diagnostics(back);
    EXPECT_FALSE(fs::exists(m_dir / "scenes" / "d.txt"));
}

TEST_F(FileIo, TypeChecksAndMisuse) {
    write(m_dir / "scenes" / "d.txt", "\"text\", 5\n");
    ParseResult r = parse("#declare N = 1;\n#fopen In \"d.txt\" read\n#read (In, N)\n");
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.diagnostics[0].message, "#read found a string for 'N', which holds a number");
    r = parse("#fopen In \"d.txt\" read\n#write (In, 1)\n");
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.diagnostics[0].message, "'In' was opened for reading; #write needs write or append");
    r = parse("#read (Nope, A)\n");
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.diagnostics[0].message, "'Nope' is not an open file (it was never opened or was closed)");
    r = parse("#fopen In \"missing.txt\" read\n");
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.diagnostics[0].message, "cannot open 'missing.txt' for reading: no such file");
}

}  // namespace
}  // namespace wardray::parser

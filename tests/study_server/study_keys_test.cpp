// The study's secret and keys (web/study_server/study_keys.hpp): the secret file is private and
// made once; keys are HMAC-SHA256 as the header defines them, checked against the openssl command
// (an implementation outside the code); a file that is not private is refused. And the answer's
// form text (web/study_server/form_text.hpp): strict, nothing half-read.
#include <sys/stat.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "tests/cli/run_command.hpp"
#include "web/study_server/form_text.hpp"
#include "web/study_server/study_keys.hpp"

namespace vimg::web {
namespace {

namespace fs = std::filesystem;

fs::path fresh_dir(const std::string& name) {
  const fs::path dir = fs::path(VIMG_BINARY_DIR) / "study_server_tests" / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

StudyKeys open_keys(const fs::path& dir) {
  auto keys = StudyKeys::open(dir);
  if (const auto* error = std::get_if<std::string>(&keys)) ADD_FAILURE() << *error;
  return std::get<StudyKeys>(keys);
}

std::string read_all(const fs::path& path) {
  std::ifstream in(path);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

TEST(StudyKeys, TheSecretIsMadeOncePrivateAndKeysSurviveReopening) {
  const fs::path dir = fresh_dir("made_once");
  const StudyKeys first = open_keys(dir);
  const fs::path file = dir / kStudySecretFile;
  struct stat st {};
  ASSERT_EQ(::stat(file.c_str(), &st), 0);
  EXPECT_EQ(st.st_mode & 0777, 0600u);
  const std::string secret = read_all(file);
  ASSERT_EQ(secret.size(), 65u);
  const StudyKeys again = open_keys(dir);
  EXPECT_EQ(read_all(file), secret);
  EXPECT_EQ(again.participant_key("p1"), first.participant_key("p1"));
  EXPECT_EQ(again.researcher_key(), first.researcher_key());
  // At least 128 bits, distinct per participant and from the researcher's, and another folder's
  // secret gives other keys.
  EXPECT_EQ(first.participant_key("p1").size(), 32u);
  EXPECT_NE(first.participant_key("p1"), first.participant_key("p2"));
  EXPECT_NE(first.participant_key("p1"), first.researcher_key());
  EXPECT_NE(open_keys(fresh_dir("made_once_other")).participant_key("p1"), first.participant_key("p1"));
}

TEST(StudyKeys, KeysAreHmacSha256OfTheSecretAsTheOpensslCommandComputesThem) {
  const fs::path dir = fresh_dir("hmac");
  const StudyKeys keys = open_keys(dir);
  std::string secret = read_all(dir / kStudySecretFile);
  secret.pop_back();
  const auto openssl = [&](const std::string& printf_text) {
    const test::CommandRun run = test::run_command("printf '" + printf_text + "' | openssl dgst -sha256 -mac HMAC -macopt hexkey:" + secret);
    EXPECT_EQ(run.exit_code, 0) << run.out;
    const std::size_t at = run.out.rfind("= ");
    return at == std::string::npos ? std::string() : run.out.substr(at + 2, 32);
  };
  EXPECT_EQ(keys.participant_key("demo"), openssl("vimg participant\\000demo"));
  EXPECT_EQ(keys.researcher_key(), openssl("vimg researcher\\000"));
}

TEST(StudyKeys, ComparisonsTakeOnlyTheRightKey) {
  std::array<unsigned char, kStudySecretBytes> secret{};
  secret[0] = 7;
  const StudyKeys keys(secret);
  const std::string key = keys.participant_key("p1");
  EXPECT_TRUE(keys.is_participant_key("p1", key));
  std::string upper = key;
  for (char& c : upper) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  EXPECT_TRUE(keys.is_participant_key("p1", upper));  // hex digits in either case
  EXPECT_FALSE(keys.is_participant_key("p2", key));   // another participant's key
  EXPECT_FALSE(keys.is_researcher_key(key));
  EXPECT_FALSE(keys.is_participant_key("p1", ""));
  EXPECT_FALSE(keys.is_participant_key("p1", key.substr(0, 31)));
  EXPECT_FALSE(keys.is_participant_key("p1", key + "0"));
  std::string flipped = key;
  flipped[31] = flipped[31] == '0' ? '1' : '0';
  EXPECT_FALSE(keys.is_participant_key("p1", flipped));
  EXPECT_TRUE(keys.is_researcher_key(keys.researcher_key()));
}

TEST(StudyKeys, ASecretOthersCanReadALinkOrBadContentIsRefused) {
  const fs::path dir = fresh_dir("refused");
  open_keys(dir);
  const fs::path file = dir / kStudySecretFile;
  fs::permissions(file, fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
  auto opened = StudyKeys::open(dir);
  ASSERT_TRUE(std::holds_alternative<std::string>(opened));
  EXPECT_NE(std::get<std::string>(opened).find("has mode 0640"), std::string::npos) << std::get<std::string>(opened);

  const fs::path linked = fresh_dir("refused_link");
  fs::create_symlink(file, linked / kStudySecretFile);
  opened = StudyKeys::open(linked);
  ASSERT_TRUE(std::holds_alternative<std::string>(opened));
  EXPECT_NE(std::get<std::string>(opened).find("symbolic link"), std::string::npos);

  const fs::path bad = fresh_dir("refused_content");
  { std::ofstream(bad / kStudySecretFile) << "not hex\n"; }
  fs::permissions(bad / kStudySecretFile, fs::perms::owner_read | fs::perms::owner_write);
  opened = StudyKeys::open(bad);
  ASSERT_TRUE(std::holds_alternative<std::string>(opened));
  EXPECT_NE(std::get<std::string>(opened).find("64 hex digits"), std::string::npos);
}

TEST(FormText, ReadsFieldsAndRefusesAnythingAmbiguous) {
  const FormFields form = parse_form_text("a=1&b=x+y%2Cz&c=");
  ASSERT_TRUE(form.ok()) << form.error;
  EXPECT_EQ(form.get("a"), "1");
  EXPECT_EQ(form.get("b"), "x y,z");
  EXPECT_EQ(form.get("c"), "");
  EXPECT_FALSE(form.get("d"));
  for (const char* bad : {"a=1&a=2", "a", "=1", "a=1&", "a=%2", "a=%zz", "a=%0A", "a=\x01"}) {
    EXPECT_FALSE(parse_form_text(bad).ok()) << bad;
    EXPECT_TRUE(parse_form_text(bad).fields.empty()) << bad;
  }
  std::string many;
  for (std::size_t i = 0; i <= kMaxFormFields; ++i) many += (i ? "&f" : "f") + std::to_string(i) + "=1";
  EXPECT_FALSE(parse_form_text(many).ok());
  EXPECT_EQ(parse_form_text("u=" + form_escape("Mozilla/5.0 (X11; Linux, x86_64) a&b=c")).get("u"),
            "Mozilla/5.0 (X11; Linux, x86_64) a&b=c");
}

}  // namespace
}  // namespace vimg::web

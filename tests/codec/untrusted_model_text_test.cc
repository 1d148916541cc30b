// A model text from the network (codec/untrusted_model_text.h, issue 38 finding 1): it names no
// file of this host (the refusal is the same whether the path exists or not, and never quotes
// it), and every size is bounded and refused by name, before anything is built.
#include <gtest/gtest.h>

#include <string>

#include "codec/untrusted_model_text.h"
#include "core/model_error.h"

namespace gc::codec {
namespace {

const std::string kCatalog = GC_BUNDLED_CATALOG_DIR;

/// The InvalidInput parse_untrusted_model_text throws for `text` (fails the test if none).
InvalidInput refusal_of(const std::string& text, const ModelTextLimits& limits = {}) {
  try {
    parse_untrusted_model_text(text, "model swap for c", kCatalog, limits);
  } catch (const InvalidInput& error) {
    return error;
  }
  ADD_FAILURE() << "accepted: " << text.substr(0, 200);
  return InvalidInput("none", "none");
}

std::string with_coupling_file(const std::string& path) {
  return "name: \"x\"\ncoupling_file: \"" + path + "\"\n";
}

TEST(UntrustedModelText, ACouplingFileIsRefusedTheSameWhetherItExistsOrNot) {
  const InvalidInput passwd = refusal_of(with_coupling_file("/etc/passwd"));
  EXPECT_EQ(passwd.field(), "model.coupling_file");
  EXPECT_EQ(std::string(passwd.what()).find("root"), std::string::npos) << passwd.what();
  EXPECT_EQ(std::string(passwd.what()).find("passwd"), std::string::npos) << passwd.what();
  for (const char* path : {"/nonexistent/c.textproto", "/dev/zero", "../../etc/shadow",
                           GC_BUNDLED_CATALOG_DIR "/nrel_upwind.textproto", "c.textproto"}) {
    const InvalidInput other = refusal_of(with_coupling_file(path));
    EXPECT_EQ(other.field(), "model.coupling_file") << path;
    EXPECT_STREQ(other.what(), passwd.what()) << path;
  }
}

TEST(UntrustedModelText, EverySizeIsBoundedAndRefusedNamingTheFieldItsSizeAndTheRange) {
  const ModelTextLimits limits;
  const InvalidInput text = refusal_of(std::string(limits.text_bytes + 1, ' '));
  EXPECT_EQ(text.field(), "model");
  EXPECT_NE(std::string(text.what()).find("65537 bytes of model text, allowed 0 to 65536"), std::string::npos)
      << text.what();
  const InvalidInput name = refusal_of("name: \"" + std::string(200, 'n') + "\" coupling: \"nrel_upwind\"");
  EXPECT_EQ(name.field(), "model.name");
  EXPECT_NE(std::string(name.what()).find("200 bytes, allowed 0 to 128"), std::string::npos) << name.what();
  const InvalidInput description =
      refusal_of("description: \"" + std::string(2000, 'd') + "\" coupling: \"nrel_upwind\"");
  EXPECT_EQ(description.field(), "model.description");
  const InvalidInput coupling = refusal_of("coupling: \"" + std::string(300, 'c') + "\"");
  EXPECT_EQ(coupling.field(), "model.coupling");
  // An expression of 65 terms: one more than an effect may have.
  std::string terms;
  for (int p = 2; p <= 66; ++p) {
    terms += "parameters { name: \"time_cycle_" + std::to_string(p) + "s_sin_on_y\" value: 1 } ";
  }
  const InvalidInput expression =
      refusal_of("coupling: \"nrel_upwind\" effects { name: \"expression\" " + terms + "}");
  EXPECT_EQ(expression.field(), "model.effects[0].parameters");
  EXPECT_NE(std::string(expression.what()).find("65 parameters, allowed 0 to 64"), std::string::npos)
      << expression.what();
  std::string effects;
  for (int e = 0; e < 33; ++e) effects += "effects { name: \"friction\" } ";
  EXPECT_EQ(refusal_of("coupling: \"nrel_upwind\" " + effects).field(), "model.effects");
}

TEST(UntrustedModelText, ABundledModelIsTakenAsItsFile) {
  const ModelFile file = parse_untrusted_model_text(
      "name: \"paper\" coupling: \"nrel_upwind\" effects { name: \"friction\" }", "swap", kCatalog);
  EXPECT_EQ(file.name, "paper");
  EXPECT_EQ(file.coupling, "nrel_upwind");
  EXPECT_EQ(file.model.effects().size(), 1u);
}

}  // namespace
}  // namespace gc::codec

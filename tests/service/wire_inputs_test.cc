// The request conversions of protocol/wire_inputs.h, without DDS: every ContactOptions member
// the core reads reaches the service unchanged; names are bounded; error texts are cut short
// (protocol/reply_status.h).
#include "protocol/wire_inputs.h"

#include <gtest/gtest.h>

#include <string>

#include "core/model_error.h"
#include "protocol/reply_status.h"

namespace gc {
namespace {

TEST(WireInputs, ContactOptionsRoundTripEveryMember) {
  for (bool continuous : {false, true}) {
    ContactOptions options;
    options.load_sharing.tolerance = 1e-7;
    options.load_sharing.max_iterations = 42;
    options.slices = 16;
    options.spacing_error_m = 2e-5;
    options.min_load_fraction = 0.8;
    options.continuous_quarter_sums = continuous;  // issue 8, docs/model.md
    gearcoupling_ContactOptions wire{};
    protocol::to_wire(options, wire);
    EXPECT_EQ(wire.continuous_quarter_sums, continuous);
    const ContactOptions back = protocol::from_wire(wire);
    EXPECT_EQ(back.continuous_quarter_sums, continuous);
    EXPECT_EQ(back.load_sharing.tolerance, 1e-7);
    EXPECT_EQ(back.load_sharing.max_iterations, 42);
    EXPECT_EQ(back.slices, 16);
    EXPECT_EQ(back.spacing_error_m, 2e-5);
    EXPECT_EQ(back.min_load_fraction, 0.8);
  }
}

/// A catalogue reference on the wire naming `name` (the memory is the string's own).
gearcoupling_CouplingRef catalogue_ref(std::string& name) {
  gearcoupling_CouplingRef wire{};
  wire._d = gearcoupling_COUPLING_FROM_CATALOGUE;
  wire._u.catalogue_name = name.data();
  return wire;
}

/// The InvalidInput from_wire(`wire`) throws.
InvalidInput rejection(const gearcoupling_CouplingRef& wire) {
  try {
    protocol::from_wire(wire);
    ADD_FAILURE() << "accepted";
  } catch (const InvalidInput& e) {
    return e;
  }
  return InvalidInput("(accepted)", "");
}

TEST(WireInputs, CatalogueNameUpTo256BytesPassesLongerIsRejectedShortly) {
  std::string name(protocol::kMaxNameBytes, 'n');
  const protocol::CouplingRef ref = protocol::from_wire(catalogue_ref(name));
  EXPECT_EQ(std::get<protocol::CatalogueName>(ref).name, name);

  for (std::size_t bytes : {protocol::kMaxNameBytes + 1, std::size_t{10} << 20}) {
    std::string long_name(bytes, 'x');
    const InvalidInput e = rejection(catalogue_ref(long_name));
    EXPECT_EQ(e.field(), "coupling.catalogue_name");
    const std::string message = e.what();
    EXPECT_LT(message.size(), 200u) << message;  // issue 9: a 10 MB name was echoed whole
    EXPECT_NE(message.find(std::to_string(bytes) + " bytes in all"), std::string::npos) << message;
    EXPECT_NE(message.find("at most 256 bytes"), std::string::npos) << message;
  }
}

TEST(WireInputs, InlineDefinitionNameIsBoundedToo) {
  std::string long_name(protocol::kMaxNameBytes + 1, 'd');
  gearcoupling_CouplingRef wire{};
  wire._d = gearcoupling_COUPLING_INLINE;
  wire._u.definition.name = long_name.data();
  EXPECT_EQ(rejection(wire).field(), "coupling.name");
}

TEST(WireInputs, UnknownCouplingSourceIsRejectedNamingTheCoupling) {
  gearcoupling_CouplingRef wire{};
  wire._d = static_cast<gearcoupling_CouplingSource>(7);
  EXPECT_EQ(rejection(wire).field(), "coupling");
}

TEST(EchoText, ShortTextIsUnchangedLongTextIsCutAndSaysHowLong) {
  EXPECT_EQ(protocol::echo_text("abc", 10), "abc");
  const std::string cut = protocol::echo_text(std::string(5000, 'a'), 100);
  EXPECT_LE(cut.size(), 100u);
  EXPECT_EQ(cut.rfind(std::string(40, 'a'), 0), 0u) << cut;
  EXPECT_NE(cut.find("(5000 bytes in all)"), std::string::npos) << cut;
}

TEST(EchoText, NeverCutsAUtf8CharacterInTwo) {
  std::string text;
  for (int i = 0; i < 100; ++i) text += "\u00b7";  // 2 bytes each
  for (std::size_t max = 30; max < 40; ++max) {
    const std::string cut = protocol::echo_text(text, max);
    const std::size_t kept = cut.find(" ... (");
    ASSERT_NE(kept, std::string::npos) << cut;
    EXPECT_EQ(kept % 2, 0u) << "cut inside a character at " << max;
  }
}

TEST(EchoText, ErrorRepliesCarryAtMostKMaxEchoBytes) {
  const std::string huge(1 << 20, 'z');
  const protocol::ReplyError error = protocol::reply_error_from(
      std::make_exception_ptr(InvalidInput(huge, "a field named by a huge string")));
  EXPECT_EQ(error.status, gearcoupling_STATUS_INVALID_INPUT);
  EXPECT_LE(error.field.size(), protocol::kMaxEchoBytes);
  EXPECT_LE(error.message.size(), protocol::kMaxEchoBytes);
  const protocol::ReplyError small =
      protocol::reply_error_from(std::make_exception_ptr(InvalidInput("f", 2.0, "[0, 1]")));
  EXPECT_EQ(small.message, "f = 2 is out of range: allowed [0, 1]");  // untouched
}

TEST(ReplyStatus, DeadlineExceededHasItsOwnStatusAndNoField) {
  const protocol::ReplyError error = protocol::reply_error_from(
      std::make_exception_ptr(protocol::DeadlineExceeded("too late")));
  EXPECT_EQ(error.status, gearcoupling_STATUS_DEADLINE_EXCEEDED);
  EXPECT_EQ(error.field, "");
  EXPECT_EQ(error.message, "too late");
  EXPECT_STREQ(protocol::to_string(gearcoupling_STATUS_DEADLINE_EXCEEDED),
               "STATUS_DEADLINE_EXCEEDED");
}

}  // namespace
}  // namespace gc

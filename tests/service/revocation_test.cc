// Revocation with a CRL (docs/security.md, "Revoking an identity"): make-security.sh --revoke puts
// a certificate on the identity CA's CRL, every security.xml names the CRL, and Cyclone's
// authentication plugin then refuses that identity, with certificates made at test time.
#include <signal.h>

#include <chrono>
#include <cstdio>
#include <algorithm>
#include <filesystem>
#include <vector>
#include <memory>
#include <string>

#include <gtest/gtest.h>

#include "client/client.h"
#include "client/client_error.h"
#include "protocol/calculation_traits.h"
#include "protocol/dds_entity.h"
#include "tests/cli/run_process.h"
#include "tests/service/secure_cell.h"
#include "tests/service/secure_cell_test.h"
#include "tests/service/service_process.h"

namespace gc {
namespace {

using protocol::Calculation;
using protocol::CatalogueName;

// Local ids of the in-process identities' domains (all on test_domain() on the wire).
constexpr int kClientADomain = 220;
constexpr int kRevokedDomain = 221;
constexpr int kRevokedWithCrlDomain = 222;
constexpr int kValidDomain = 223;
constexpr int kRevokedLaterDomain = 224;

constexpr const char* kLoopback = "file://" GC_SOURCE_DIR "/deploy/cyclonedds-loopback.xml";

class Revocation : public test::SecureCellTest {
 protected:
  void SetUp() override {
    make_cell();
    if (!IsSkipped()) cell_->rerun("--revoke client-b");
  }
  client::ClientOptions options(int local_id, const std::string& name) const {
    return {local_id, std::chrono::seconds(10), cell_->client_prefix(name)};
  }
  /// client-b's own security.xml without the CRL: what a revoked client controls on its host.
  std::string revoked_config_without_crl() const {
    std::string config = cli::testing::read_file(cell_->dir() + "/client-b/security.xml");
    const std::size_t begin = config.find("<CRL>");
    config.erase(begin, config.find("</CRL>") + 6 - begin);
    const std::string path = cell_->dir() + "/client-b-no-crl.xml";
    cli::testing::write_file(path, config);
    return std::string(kLoopback) + ",file://" + path;
  }
};

TEST_F(Revocation, TheCrlListsTheRevokedCertificateOnlyAndEveryConfigurationNamesIt) {
  const std::string& d = cell_->dir();
  const std::string check = "openssl verify -crl_check -CRLfile " + d + "/ca/identity_crl.pem -CAfile " +
                            d + "/ca/identity_ca.pem ";
  EXPECT_EQ(test::run_shell(check + d + "/client-a/cert.pem").exit_code, 0);
  const test::ShellResult revoked = test::run_shell(check + d + "/client-b/cert.pem");
  EXPECT_NE(revoked.exit_code, 0);
  EXPECT_NE(revoked.output.find("certificate revoked"), std::string::npos) << revoked.output;
  for (const std::string identity : {"service-main", "client-a", "client-b", "dashboard-main"}) {
    EXPECT_NE(cli::testing::read_file(d + "/" + identity + "/security.xml")
                  .find("<CRL>file:" + d + "/ca/identity_crl.pem</CRL>"),
              std::string::npos) << identity;
  }
}

TEST_F(Revocation, ARerunWithOrWithoutTheRevocationChangesNoFile) {
  const auto before = cell_->files();
  cell_->rerun("--revoke client-b");
  EXPECT_EQ(cell_->files(), before);
  cell_->rerun({});  // revoked for good: the database keeps it
  EXPECT_EQ(cell_->files(), before);
}

TEST_F(Revocation, ABadOrUnknownIdentityIsRefusedNamingIt) {
  const std::string script = GC_SOURCE_DIR "/deploy/security/make-security.sh " + cell_->dir();
  const test::ShellResult bad = test::run_shell(script + " --revoke b");
  EXPECT_EQ(bad.exit_code, 1);
  EXPECT_NE(bad.output.find("--revoke \"b\": allowed an identity ROLE-NAME, ROLE one of service "
                            "client dashboard console monitor cell operator"),
            std::string::npos) << bad.output;
  const test::ShellResult unknown = test::run_shell(script + " --client a --revoke client-zz");
  EXPECT_EQ(unknown.exit_code, 1);
  EXPECT_NE(unknown.output.find("--revoke client-zz: no certificate"), std::string::npos)
      << unknown.output;
}

TEST_F(Revocation, ARevokedClientFindsNoServiceAndANonRevokedOneWithTheSameCrlIsAnswered) {
  test::ServiceProcess service({}, cell_->dir() + "/service.log",
                               {{"CYCLONEDDS_URI", cell_->uri("service-main")}});
  // client-a, not revoked, with the same CRL: answered (so discovery has run its course).
  const test::LocalDomain a(kClientADomain, cell_->uri("client-a"));
  client::Client answered(options(kClientADomain, "a"));
  EXPECT_GT(answered.call<Calculation::kJamAngle>({CatalogueName{"nrel_upwind"}}).jam.angle_rad, 0.0);

  // client-b, revoked, with a configuration that leaves the CRL out: it authenticates nobody
  // and nobody authenticates it, so it never sees the service's status nor gets an answer.
  const test::LocalDomain b(kRevokedDomain, revoked_config_without_crl());
  client::Client revoked(options(kRevokedDomain, "b"));
  EXPECT_THROW(revoked.call<Calculation::kJamAngle>({CatalogueName{"nrel_upwind"}}), client::Timeout);
  EXPECT_TRUE(revoked.instances().empty());
  EXPECT_EQ(revoked.counters().replies, 0u);
  // client-a is still answered afterwards.
  EXPECT_GT(answered.call<Calculation::kJamAngle>({CatalogueName{"nrel_upwind"}}).jam.angle_rad, 0.0);
}

TEST_F(Revocation, ARevokedIdentityWithTheCrlCannotJoinTheDomain) {
  const test::LocalDomain b(kRevokedWithCrlDomain, cell_->uri("client-b"));
  EXPECT_THROW(b.participant(), protocol::DdsError);
}

// Revocation without a restart (issue 23, finding 5): the service re-reads the CRL on SIGHUP by
// making a new participant. client-b, answered until then, is revoked while both run; after the
// SIGHUP client-a is answered again and client-b gets nothing.
class RevocationOnSighup : public test::SecureCellTest {
 protected:
  void SetUp() override { make_cell(); }
};

TEST_F(RevocationOnSighup, ARevokedClientGetsNothingAfterSighupWhileAValidOneIsAnsweredAgain) {
  using Clock = std::chrono::steady_clock;
  const std::string log = cell_->dir() + "/service.log";
  test::ServiceProcess service({}, log, {{"CYCLONEDDS_URI", cell_->uri("service-main")}});
  const CatalogueName upwind{"nrel_upwind"};
  const test::LocalDomain a(kValidDomain, cell_->uri("client-a"));
  const test::LocalDomain b(kRevokedLaterDomain, cell_->uri("client-b"));
  client::Client valid({kValidDomain, std::chrono::seconds(2), cell_->client_prefix("a")});
  client::Client revoked({kRevokedLaterDomain, std::chrono::seconds(2), cell_->client_prefix("b")});
  ASSERT_TRUE(valid.wait_for_service(Calculation::kJamAngle, std::chrono::seconds(30)));
  ASSERT_TRUE(revoked.wait_for_service(Calculation::kJamAngle, std::chrono::seconds(30)));
  EXPECT_GT(valid.call<Calculation::kJamAngle>({upwind}).jam.angle_rad, 0.0);
  EXPECT_GT(revoked.call<Calculation::kJamAngle>({upwind}).jam.angle_rad, 0.0);  // before

  const std::vector<client::InstanceInfo> before = valid.instances();
  ASSERT_EQ(before.size(), 1u);
  cell_->rerun("--revoke client-b");  // a new ca/identity_crl.pem, read by no process yet
  const Clock::time_point hup = Clock::now();
  service.signal(SIGHUP);
  // The valid client calls back to back (each call up to 2 s) until the new instance (a new
  // participant, so a new id) has answered it; bounded at 30 s. The interruption is the longest
  // time between two answers (the first counted from the signal).
  Clock::time_point last_answer = hup;
  double interruption_s = 0.0;
  int failed_calls = 0;
  bool new_instance_answered = false;
  while (!new_instance_answered && Clock::now() - hup < std::chrono::seconds(30)) {
    const std::vector<client::InstanceInfo> now_known = valid.instances();
    const bool only_new = now_known.size() == 1 && now_known[0].id != before[0].id;
    try {
      valid.call<Calculation::kJamAngle>({upwind});
      const Clock::time_point answered_at = Clock::now();
      interruption_s = std::max(interruption_s,
                                std::chrono::duration<double>(answered_at - last_answer).count());
      last_answer = answered_at;
      new_instance_answered = only_new;
    } catch (const std::exception&) {
      failed_calls += 1;
    }
  }
  std::printf("SIGHUP: the valid client went %.3f s without an answer (%d calls failed), then "
              "was answered by the new instance\n",
              interruption_s, failed_calls);
  ASSERT_TRUE(new_instance_answered)
      << "the valid client was not answered by a new instance within 30 s of the SIGHUP: "
      << cli::testing::read_file(log);
  EXPECT_TRUE(service.running());
  // After the interruption: the valid client keeps being answered, 20 of 20; the revoked one
  // gets nothing, every call times out (2 s each, 3 calls: bounded).
  int answered = 0;
  for (int k = 0; k < 20; ++k) {
    try {
      valid.call<Calculation::kJamAngle>({upwind});
      answered += 1;
    } catch (const std::exception&) {
    }
  }
  EXPECT_EQ(answered, 20);
  const std::uint64_t replies_before = revoked.counters().replies;
  for (int k = 0; k < 3; ++k) {
    EXPECT_THROW(revoked.call<Calculation::kJamAngle>({upwind}), client::Timeout) << k;
  }
  EXPECT_EQ(revoked.counters().replies, replies_before);
  EXPECT_TRUE(revoked.instances().empty());
}

}  // namespace
}  // namespace gc

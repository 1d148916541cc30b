// Revocation with a CRL (docs/security.md, "Revoking an identity"): make-security.sh --revoke puts
// a certificate on the identity CA's CRL, every security.xml names the CRL, and Cyclone's
// authentication plugin then refuses that identity, with certificates made at test time.
#include <filesystem>
#include <memory>
#include <string>

#include <gtest/gtest.h>

#include "clients/remote/client.h"
#include "clients/remote/client_error.h"
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

}  // namespace
}  // namespace gc

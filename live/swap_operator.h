// Who puts a model in force, as the monitor's audit trail names them (`by`): a person, not a
// process. Under DDS Security the operator identity's subject (CN=operator-NAME, the certificate
// deploy/security/make-security.sh makes) names them; otherwise the operator names themself with
// `--operator NAME`, which `gearcoupling swap-model` and a dashboard with --operator-cells then
// require. Both edges resolve it here, so the trail reads the same from either.
#pragma once

#include <string>
#include <string_view>

namespace gc::live {

/// Longest operator name [characters]: the audit trail keeps 128 bytes of a swap's claims.
inline constexpr std::size_t kMaxOperatorNameChars = 64;

/// Who swaps, for the audit trail's `by`:
/// - `operator_flag` (the `--operator NAME` given) when not empty: 1 to kMaxOperatorNameChars
///   printable ASCII characters, neither ';' nor '=' (they delimit the writer's USER_DATA);
/// - else `identity_operator` NAME (live::operator_of_identity(), the process's DDS Security
///   identity operator-NAME) as "operator-NAME", its certificate subject's common name;
/// - else throws InvalidInput naming "--operator": the name is required.
/// A bad `operator_flag` throws InvalidInput naming "--operator", the value and what is allowed.
std::string swap_operator(std::string_view operator_flag, std::string_view identity_operator);

/// "by=BY;source=SOURCE", the USER_DATA of a swap writer (live/model_swap_publisher.h) that the
/// monitor reads into its audit trail.
std::string swap_user_data(std::string_view by, std::string_view source);

}  // namespace gc::live

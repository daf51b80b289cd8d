package net.smc.core.role;

import java.util.Objects;
import net.smc.policy.PolicyEngine;
import net.smc.policy.api.PolicyRepository;
import net.smc.policy.RunResult;

/**
 * Where one policy file of a role comes from: a repository URI ({@code policy:/roles/surveyor/mission},
 * the normal case, named by mission specifications) or PonderTalk text carried inline (a policy
 * sent in a role-assignment message, or a test). Its {@link #label()} identifies it: the Role-Manager
 * loads a label once per role, and names it in errors.
 */
public sealed interface PolicySource {

    /** The URI, or the inline text's name. */
    String label();

    /** Runs the file as one unit in the cell. */
    RunResult runIn(PolicyEngine cell);

    static PolicySource uri(String uri) {
        return new Uri(uri);
    }

    static PolicySource text(String name, String text) {
        return new Text(name, text);
    }

    /** A file of the policy repository, loaded with {@link PolicyEngine#load(String)}. */
    record Uri(String uri) implements PolicySource {
        public Uri {
            Objects.requireNonNull(uri, "uri");
            String prefix = PolicyRepository.SCHEME + "/";
            if (!uri.startsWith(prefix) || uri.length() == prefix.length()) {
                throw new IllegalArgumentException("policy URI '" + uri + "' must start with 'policy:/' and name a file");
            }
        }

        @Override
        public String label() {
            return uri;
        }

        @Override
        public RunResult runIn(PolicyEngine cell) {
            return cell.load(uri);
        }
    }

    /** PonderTalk text; {@code name} is its source name in diagnostics. */
    record Text(String name, String text) implements PolicySource {
        public Text {
            Objects.requireNonNull(text, "text");
            if (name == null || name.isBlank()) {
                throw new IllegalArgumentException("an inline policy needs a name for its diagnostics, got '" + name + "'");
            }
        }

        @Override
        public String label() {
            return name;
        }

        @Override
        public RunResult runIn(PolicyEngine cell) {
            return cell.run(name, text);
        }
    }
}

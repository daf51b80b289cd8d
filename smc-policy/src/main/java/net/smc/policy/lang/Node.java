package net.smc.policy.lang;

import java.util.List;

/**
 * The PonderTalk abstract syntax tree: one closed family of immutable nodes. The parser builds it;
 * the interpreter compiles it into executable code. Every node knows where it came from.
 */
public sealed interface Node {

    SourcePos pos();

    /** A number ({@link java.math.BigDecimal}), string or boolean written in the source. */
    record Literal(SourcePos pos, Object value) implements Node {
    }

    /**
     * A name or path as written: {@code x}, {@code root/event/alarm}, or {@code /event/alarm}
     * (absolute). {@code segments} are the parts between slashes.
     */
    record Name(SourcePos pos, String text, List<String> segments, boolean absolute) implements Node {
        public Name {
            segments = List.copyOf(segments);
        }
    }

    /** {@code name := value}. */
    record Assign(SourcePos pos, String name, Node value) implements Node {
    }

    /** {@code #( ... )}: elements are evaluated when the literal is. */
    record ArrayLiteral(SourcePos pos, List<Node> elements) implements Node {
        public ArrayLiteral {
            elements = List.copyOf(elements);
        }
    }

    /** {@code [:a :b | statements]}. */
    record BlockLiteral(SourcePos pos, List<String> params, List<Node> statements) implements Node {
        public BlockLiteral {
            params = List.copyOf(params);
            statements = List.copyOf(statements);
        }
    }

    /** A message sent to the value of {@code receiver}; the position is the message's. */
    record Send(Node receiver, Message message) implements Node {
        @Override
        public SourcePos pos() {
            return message.pos();
        }
    }

    /**
     * {@code r m1 m2; m3; m4}: {@code receiver} is evaluated once; each chain of messages is then
     * sent starting from it ({@code m2}, then {@code m3}, then {@code m4}); the value is the last
     * chain's.
     */
    record Cascade(SourcePos pos, Node receiver, List<List<Message>> chains) implements Node {
        public Cascade {
            chains = chains.stream().map(List::copyOf).toList();
        }
    }

    /** One message: a selector such as {@code size}, {@code +} or {@code at:put:} and its arguments. */
    record Message(SourcePos pos, String selector, List<Node> args) {
        public Message {
            args = List.copyOf(args);
        }
    }
}

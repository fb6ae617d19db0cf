// SPDX-License-Identifier: Apache-2.0
// The grammar of a part program line, in PEGTL (docs/programs.md, "Lines and words" and
// "Dialects"): blanks, words (a letter and a number or a macro expression, blanks
// allowed between them), comments in parentheses that close on the line (no '(' inside
// one, as LinuxCNC), an optional ';' comment to the end of the line, and in the LinuxCNC
// and Fanuc dialects parameter settings (#1 = 2, #<x> = 3); or one statement: HNC's
// macro statements (#n = expression, WHILE, ENDW, IF, ELSE, ENDIF), LinuxCNC's O-words
// (o100 sub, o<name> call [1] [2], o101 while [..] ...), Fanuc's program number 'O1234'.
// A '/' first deletes the block when the switch is on. Expressions are read flat, an
// operand and an operator at a time; the actions (host/program/grammar/grammar.cpp) build the tree
// with the dialect's precedence.
#pragma once

#include <tao/pegtl.hpp>

#include "host/program/grammar/line.hpp"

namespace dda::program::detail::rules {

namespace pg = tao::pegtl;

// The state a line's parse fills in (host/program/grammar/grammar.cpp); the rules read its dialect.
struct ParseState;
bool dialect_is(const ParseState& s, Dialect d);

// Matches nothing and succeeds when the line is read in one of the dialects Ds.
template <Dialect... Ds>
struct in_dialect {
  using rule_t = in_dialect;
  using subs_t = pg::empty_list;
  template <pg::apply_mode, pg::rewind_mode, template <typename...> class, template <typename...> class, typename Input,
            typename... States>
  static bool match(Input& /*in*/, const ParseState& s, States&&... /*unused*/) {
    return (dialect_is(s, Ds) || ...);
  }
};

struct blank : pg::one<' ', '\t'> {};
struct ws : pg::star<blank> {};
struct paren_open : pg::one<'('> {};
struct nested_open : pg::one<'('> {};
struct comment_body : pg::until<pg::one<')'>, pg::sor<nested_open, pg::not_one<'\r', '\n'>>> {};
struct paren_comment : pg::if_must<paren_open, comment_body> {};
struct semi_comment : pg::seq<pg::one<';'>, pg::star<pg::not_one<'\r', '\n'>>> {};
struct digits : pg::plus<pg::digit> {};
struct unsigned_number
    : pg::sor<pg::seq<digits, pg::opt<pg::one<'.'>, pg::opt<digits>>>, pg::seq<pg::one<'.'>, digits>> {};
struct number : pg::seq<pg::opt<pg::one<'+', '-'>>, unsigned_number> {};

// Keywords are whole words in any case.
template <typename Kw>
struct keyword : pg::seq<Kw, pg::not_at<pg::alnum>> {};
struct kw_pi : keyword<TAO_PEGTL_ISTRING("PI")> {};
struct kw_not : keyword<TAO_PEGTL_ISTRING("NOT")> {};
struct func_name
    : pg::sor<TAO_PEGTL_ISTRING("SIN"), TAO_PEGTL_ISTRING("COS"), TAO_PEGTL_ISTRING("TAN"), TAO_PEGTL_ISTRING("ASIN"),
              TAO_PEGTL_ISTRING("ACOS"), TAO_PEGTL_ISTRING("SQRT"), TAO_PEGTL_ISTRING("ABS"), TAO_PEGTL_ISTRING("INT"),
              TAO_PEGTL_ISTRING("FIX"), TAO_PEGTL_ISTRING("FUP"), TAO_PEGTL_ISTRING("ROUND"), TAO_PEGTL_ISTRING("EXP"),
              TAO_PEGTL_ISTRING("LN")> {};
struct word_op
    : pg::seq<
          pg::sor<TAO_PEGTL_ISTRING("EQ"), TAO_PEGTL_ISTRING("NE"), TAO_PEGTL_ISTRING("GT"), TAO_PEGTL_ISTRING("GE"),
                  TAO_PEGTL_ISTRING("LT"), TAO_PEGTL_ISTRING("LE"), TAO_PEGTL_ISTRING("AND"), TAO_PEGTL_ISTRING("OR"),
                  TAO_PEGTL_ISTRING("XOR"), TAO_PEGTL_ISTRING("MOD")>,
          pg::not_at<pg::alpha>> {};
struct binary_op : pg::sor<pg::string<'*', '*'>, pg::one<'+', '-', '*', '/'>, word_op> {};

struct expr;
struct expr_number : unsigned_number {};
struct bracket_close : pg::one<']'> {};
struct bracket : pg::if_must<pg::one<'['>, ws, expr, ws, bracket_close> {};
struct name_close : pg::one<'>'> {};
struct name_text : pg::star<pg::not_one<'>', '\r', '\n'>> {};
struct named_var : pg::seq<pg::one<'#'>, pg::one<'<'>, pg::must<name_text, name_close>> {};
struct var;
struct func;
struct var_index : pg::sor<expr_number, bracket, named_var, var, func> {};
struct var : pg::if_must<pg::one<'#'>, var_index> {};
struct var_ref : pg::sor<named_var, var> {};
struct func_arg : bracket {};
// ATAN[a]/[b]: LinuxCNC's and Fanuc's two-argument arc tangent (in HNC, '/' divides).
struct atan2_tail
    : pg::seq<in_dialect<Dialect::LinuxCnc, Dialect::Fanuc>, ws, pg::one<'/'>, ws, pg::at<pg::one<'['>>, bracket> {};
struct atan_name : TAO_PEGTL_ISTRING("ATAN") {};
struct func : pg::sor<pg::if_must<atan_name, ws, func_arg, pg::opt<atan2_tail>>, pg::if_must<func_name, ws, func_arg>> {
};
struct exists_close : pg::one<']'> {};
struct exists : pg::if_must<keyword<TAO_PEGTL_ISTRING("EXISTS")>, ws, pg::one<'['>, ws, var_ref, ws, exists_close> {};
struct primary : pg::sor<expr_number, var_ref, bracket, kw_pi, exists, func> {};
struct unary;
struct negate : pg::if_must<pg::one<'-'>, ws, unary> {};
struct unary : pg::sor<negate, pg::seq<pg::one<'+'>, ws, unary>, primary> {};
struct not_prefix : kw_not {};
struct operand : pg::seq<pg::star<not_prefix, ws>, unary> {};
struct binary_tail : pg::if_must<binary_op, ws, operand> {};
struct expr_open : pg::success {};
struct expr : pg::seq<expr_open, operand, pg::star<ws, binary_tail>> {};

// Words: a letter, then a number or an expression (#n, #<x>, [..], -#n, -[..], a function).
struct letter : pg::alpha {};
struct word_expr : pg::sor<var_ref, bracket, negate, func, exists> {};
struct word_value : pg::sor<number, word_expr> {};
struct word : pg::if_must<letter, ws, word_value> {};
struct end_of_line : pg::eolf {};
struct tail : pg::seq<pg::star<pg::sor<blank, paren_comment>>, pg::opt<semi_comment>, pg::must<end_of_line>> {};

// A parameter set among the words (LinuxCNC, Fanuc).
struct set_eq : pg::one<'='> {};
struct param_set : pg::seq<in_dialect<Dialect::LinuxCnc, Dialect::Fanuc>, pg::at<pg::one<'#'>>, var_ref, ws,
                           pg::must<set_eq>, ws, pg::must<expr>> {};

// HNC's statements.
struct assign_eq : pg::one<'='> {};
struct assignment : pg::if_must<pg::one<'#'>, var_index, ws, assign_eq, ws, expr> {};
struct kw_while : keyword<TAO_PEGTL_ISTRING("WHILE")> {};
struct kw_endw : keyword<TAO_PEGTL_ISTRING("ENDW")> {};
struct kw_if : keyword<TAO_PEGTL_ISTRING("IF")> {};
struct kw_else : keyword<TAO_PEGTL_ISTRING("ELSE")> {};
struct kw_endif : keyword<TAO_PEGTL_ISTRING("ENDIF")> {};
struct while_stmt : pg::if_must<kw_while, ws, expr> {};
struct if_stmt : pg::if_must<kw_if, ws, expr> {};
struct statement : pg::sor<assignment, while_stmt, kw_endw, if_stmt, kw_else, kw_endif> {};
struct n_word : pg::seq<pg::at<pg::one<'N', 'n'>>, word> {};
// A statement line is recognised by looking ahead (actions are off inside at<>), so that
// no action of a line read as words has run when it turns out to be a statement.
struct statement_start : pg::sor<pg::one<'#'>, kw_while, kw_endw, kw_if, kw_else, kw_endif> {};
struct n_raw : pg::seq<pg::one<'N', 'n'>, ws, number> {};
struct lead : pg::star<pg::sor<blank, paren_comment>> {};  // blanks and comments before a statement
struct hnc_statement_line : pg::seq<in_dialect<Dialect::Hnc>, pg::at<lead, pg::opt<n_raw, lead>, statement_start>, lead,
                                    pg::opt<n_word, lead>, statement, tail> {};

// LinuxCNC's O-words: o<number or <name>> keyword [arguments].
struct o_name_text : pg::plus<pg::not_one<'>', '\r', '\n'>> {};
// A name computed from a parameter (o#<sub> call, o#1 call): the subroutine whose number
// the parameter holds.
struct o_computed : pg::seq<pg::at<pg::one<'#'>>, var_ref> {};
struct o_name : pg::sor<pg::seq<pg::one<'<'>, pg::must<o_name_text, name_close>>, digits, o_computed> {};
template <Stmt K, typename Kw>
struct o_kw : keyword<Kw> {
  static constexpr Stmt kind = K;
};
struct o_sub : o_kw<Stmt::OSub, TAO_PEGTL_ISTRING("SUB")> {};
struct o_endsub : o_kw<Stmt::OEndSub, pg::seq<TAO_PEGTL_ISTRING("END"), ws, TAO_PEGTL_ISTRING("SUB")>> {};
struct o_call : o_kw<Stmt::OCall, TAO_PEGTL_ISTRING("CALL")> {};
struct o_return : o_kw<Stmt::OReturn, TAO_PEGTL_ISTRING("RETURN")> {};
struct o_if : o_kw<Stmt::OIf, TAO_PEGTL_ISTRING("IF")> {};
struct o_elseif : o_kw<Stmt::OElseIf, pg::seq<TAO_PEGTL_ISTRING("ELSE"), ws, TAO_PEGTL_ISTRING("IF")>> {};
struct o_else : o_kw<Stmt::OElse, TAO_PEGTL_ISTRING("ELSE")> {};
struct o_endif : o_kw<Stmt::OEndIf, pg::seq<TAO_PEGTL_ISTRING("END"), ws, TAO_PEGTL_ISTRING("IF")>> {};
struct o_while : o_kw<Stmt::OWhile, TAO_PEGTL_ISTRING("WHILE")> {};
struct o_endwhile : o_kw<Stmt::OEndWhile, pg::seq<TAO_PEGTL_ISTRING("END"), ws, TAO_PEGTL_ISTRING("WHILE")>> {};
struct o_do : o_kw<Stmt::ODo, TAO_PEGTL_ISTRING("DO")> {};
struct o_repeat : o_kw<Stmt::ORepeat, TAO_PEGTL_ISTRING("REPEAT")> {};
struct o_endrepeat : o_kw<Stmt::OEndRepeat, pg::seq<TAO_PEGTL_ISTRING("END"), ws, TAO_PEGTL_ISTRING("REPEAT")>> {};
struct o_break : o_kw<Stmt::OBreak, TAO_PEGTL_ISTRING("BREAK")> {};
struct o_continue : o_kw<Stmt::OContinue, TAO_PEGTL_ISTRING("CONTINUE")> {};
struct o_condition : bracket {};  // the condition, count or value
struct o_arg : bracket {};        // a call's argument
struct o_keyword_expected : pg::failure {};
struct o_statement
    : pg::sor<pg::if_must<pg::sor<o_if, o_elseif, o_while, o_repeat>, ws, o_condition>,
              pg::seq<pg::sor<o_endsub, o_return>, pg::opt<ws, pg::at<pg::one<'['>>, o_condition>>,
              pg::seq<o_call, pg::star<pg::star<pg::sor<blank, paren_comment>>, pg::at<pg::one<'['>>, o_arg>>,
              pg::sor<o_sub, o_else, o_endif, o_endwhile, o_do, o_endrepeat, o_break, o_continue>,
              pg::must<o_keyword_expected>> {};
struct o_letter : pg::one<'O', 'o'> {};
struct oword_line
    : pg::seq<in_dialect<Dialect::LinuxCnc>, pg::at<lead, pg::opt<n_raw, lead>, o_letter, ws, o_name, ws, pg::alpha>,
              lead, pg::opt<n_word, lead>, o_letter, ws, o_name, ws, o_statement, tail> {};

// Fanuc's program number: 'O1234' alone on its line (comments allowed), which LinuxCNC
// 2.9 reads too (its main program's title, or a subprogram M98 calls).
struct fanuc_number : digits {};
struct fanuc_program_line : pg::seq<in_dialect<Dialect::Fanuc, Dialect::LinuxCnc>,
                                    pg::at<lead, o_letter, digits, ws, pg::opt<paren_comment>, ws, pg::eolf>, lead,
                                    o_letter, fanuc_number, ws, tail> {};

struct block_delete : pg::one<'/'> {};
struct words_line : pg::seq<pg::star<pg::sor<blank, paren_comment, param_set, word>>, tail> {};
struct line
    : pg::seq<ws, pg::opt<block_delete>, pg::sor<fanuc_program_line, oword_line, hnc_statement_line, words_line>> {};

}  // namespace dda::program::detail::rules

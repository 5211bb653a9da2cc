"""The command line a report prints must read back, in a shell, as the arguments that ran."""
import shlex
import sys

from krp_training.command_line import invocation, quoted


def test_a_quoted_line_splits_back_into_the_same_arguments():
    args = ["--world", "my office", "--out", "models/$HOME", "a'b", 3]
    assert shlex.split(quoted(args)) == [str(a) for a in args]


def test_an_invocation_names_the_program_and_the_arguments_it_was_given():
    assert invocation("krp-train-map", ["--world", "office two"]) == "krp-train-map --world 'office two'"


def test_an_empty_argument_list_is_not_replaced_by_the_process_arguments(monkeypatch):
    monkeypatch.setattr(sys, "argv", ["prog", "--from-the-process"])
    assert invocation("krp-train-map", []) == "krp-train-map"
    assert invocation("krp-train-map") == "krp-train-map --from-the-process"

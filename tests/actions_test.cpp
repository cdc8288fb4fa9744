// actions_test.cpp — the command table: every command reachable, keys unambiguous, and the
// README's shortcut table exactly the help overlay's.
#include "test_files.h"
#include "ui/actions.h"

#include <gtest/gtest.h>

#include <set>
#include <sstream>

namespace lab {
namespace {

TEST(Commands, EveryCommandHasARowAndTheRowsNameTheirCommand) {
    std::set<Command> seen;
    for (const CommandRow& row : commandTable()) {
        seen.insert(row.command);
        EXPECT_EQ(commandRow(row.command).command, row.command);
    }
    EXPECT_EQ(seen.size(), static_cast<std::size_t>(kLastCommand) + 1) << "a command without a row";
}

TEST(Commands, NoTwoRowsShareAKey) {
    std::set<std::pair<int, unsigned>> keys;
    for (const CommandRow& row : commandTable()) {
        if (row.key != 0) {
            EXPECT_TRUE(keys.insert({row.key, row.modifiers}).second) << keyName(row.key, row.modifiers) << " is bound twice";
        }
    }
}

TEST(Commands, KeysFindTheirCommandAndPlainKeysWaitWhileTyping) {
    EXPECT_EQ(commandForKey('B', kNoModifier, false), Command::NextBrdf);
    EXPECT_EQ(commandForKey('B', kNoModifier, true), std::nullopt); // typing a "B" in a field
    EXPECT_EQ(commandForKey('B', kCtrl, false), std::nullopt);
    EXPECT_EQ(commandForKey('Z', kCtrl | kShift, false), Command::Redo);
    EXPECT_EQ(commandForKey('Z', kCtrl, true), std::nullopt); // the field's own undo
    EXPECT_EQ(commandForKey('S', kCtrl, true), Command::Save);
    EXPECT_EQ(commandForKey(keys::F12, kNoModifier, true), Command::Screenshot);
    EXPECT_EQ(commandForKey(keys::KeypadAdd, kCtrl, false), Command::PresenterLarger);
    EXPECT_EQ(commandForKey('H', kNoModifier, false), Command::TogglePanels);
    EXPECT_EQ(commandForKey(keys::Tab, kNoModifier, false), std::nullopt);
}

// In a window, the plain keys are the widget's (WCAG 2.1.4: single-key shortcuts only where the model
// has the keyboard); Ctrl shortcuts and the function keys still work.
TEST(Commands, AWidgetWithTheKeyboardKeepsThePlainKeys) {
    EXPECT_EQ(commandForKey('1', kNoModifier, KeyOwner::Canvas), Command::ShadingFlat);
    EXPECT_EQ(commandForKey('1', kNoModifier, KeyOwner::Panel), std::nullopt);
    EXPECT_EQ(commandForKey(keys::Right, kNoModifier, KeyOwner::Panel), std::nullopt);
    EXPECT_EQ(commandForKey(keys::Escape, kNoModifier, KeyOwner::Panel), std::nullopt);
    EXPECT_EQ(commandForKey('Z', kCtrl, KeyOwner::Panel), Command::Undo);
    EXPECT_EQ(commandForKey('Z', kCtrl, KeyOwner::Typing), std::nullopt);
    EXPECT_EQ(commandForKey(keys::F12, kNoModifier, KeyOwner::Panel), Command::Screenshot);
    EXPECT_EQ(commandForKey(keys::F1, kNoModifier, KeyOwner::Typing), Command::ToggleHelp);
}

// Tab is the keyboard's way into the windows (ui/keyboard.h) and a browser's between its controls: no
// command takes it, nor F5 (reload), F6 (address bar) or a Ctrl+letter that browsers keep or readers expect.
TEST(Commands, NoCommandTakesTabOrABrowsersKey) {
    for (const CommandRow& row : commandTable()) {
        EXPECT_NE(row.key, keys::Tab) << keyName(row.key, row.modifiers) << " is the keyboard navigation's";
        EXPECT_FALSE(row.key == keys::F1 + 4 || row.key == keys::F1 + 5) << keyName(row.key, row.modifiers);
        if ((row.modifiers & kCtrl) && row.key < 128) {
            EXPECT_EQ(std::string("WTNLRQPFDHJK").find(static_cast<char>(row.key)), std::string::npos)
                << keyName(row.key, row.modifiers) << " is a browser's";
        }
    }
    EXPECT_EQ(commandRow(Command::TogglePanels).key, 'H');
}

TEST(Commands, HelpJoinsABindingsOfOneCommand) {
    bool redo = false;
    for (const HelpRow& row : helpRows()) {
        if (row.help == "redo") {
            EXPECT_EQ(row.keys, "Ctrl+Y / Ctrl+Shift+Z");
            redo = true;
        }
    }
    EXPECT_TRUE(redo);
}

// The README's shortcut table holds the help overlay's rows, no more and no fewer, in order.
TEST(Commands, ReadmeShortcutTableIsTheHelpOverlay) {
    std::istringstream readme(readText(std::string(LAB_SOURCE_DIR) + "/README.md"));
    std::vector<std::string> table;
    bool inTable = false;
    for (std::string line; std::getline(readme, line);) {
        if (line == "| keys | action |") {
            inTable = true;
        } else if (inTable && line.rfind("| ", 0) == 0) {
            table.push_back(line);
        } else if (inTable && line.rfind("|---", 0) != 0) {
            break;
        }
    }
    std::vector<std::string> expected;
    for (const HelpRow& row : helpRows()) {
        expected.push_back("| " + row.keys + " | " + row.help + " |");
    }
    EXPECT_EQ(table, expected) << "regenerate the README's table from helpRows()";
}

} // namespace
} // namespace lab

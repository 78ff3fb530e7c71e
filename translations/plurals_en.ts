<?xml version='1.0' encoding='utf-8'?>
<!DOCTYPE TS>
<!-- SPDX-License-Identifier: GPL-3.0-or-later -->
<!-- English plural forms only ("1 checked move", "2 checked moves"): the sources say
     "%n checked move(s)" and English has no other translation. Loaded for English
     (app/studio/data_files.cpp); add an entry here for each new tr() with %n. -->
<TS version="2.1" language="en">
<context>
    <name>fivebar::widgets::GoToTool</name>
    <message numerus="yes">
        <source>Go to %1, %2 mm? The dashed path is the pen's travel (%n checked move(s)).</source>
        <translation>
            <numerusform>Go to %1, %2 mm? The dashed path is the pen's travel (%n checked move).</numerusform>
            <numerusform>Go to %1, %2 mm? The dashed path is the pen's travel (%n checked moves).</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>fivebar::session::MachineSession</name>
    <message numerus="yes">
        <source>%1 (jog in %n checked move(s))</source>
        <translation>
            <numerusform>%1 (jog in %n checked move)</numerusform>
            <numerusform>%1 (jog in %n checked moves)</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>fivebar::widgets::LayersPanel</name>
    <message numerus="yes">
        <source>%n path(s)</source>
        <translation>
            <numerusform>%n path</numerusform>
            <numerusform>%n paths</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n point(s)</source>
        <translation>
            <numerusform>%n point</numerusform>
            <numerusform>%n points</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>fivebar::widgets::MachineSettingsDialog</name>
    <message numerus="yes">
        <source>Write %n setting(s) to the board? Its current settings are saved to a backup file first.</source>
        <translation>
            <numerusform>Write %n setting to the board? Its current settings are saved to a backup file first.</numerusform>
            <numerusform>Write %n settings to the board? Its current settings are saved to a backup file first.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n setting(s) differ from the profile.</source>
        <translation>
            <numerusform>%n setting differs from the profile.</numerusform>
            <numerusform>%n settings differ from the profile.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n setting(s) written. Backup of the previous settings: %1</source>
        <translation>
            <numerusform>%n setting written. Backup of the previous settings: %1</numerusform>
            <numerusform>%n settings written. Backup of the previous settings: %1</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>fivebar::session::SettingsAdvice</name>
    <message numerus="yes">
        <source>The board's settings differ from the profile in %n place(s): %1.</source>
        <translation>
            <numerusform>The board's settings differ from the profile in %n place: %1.</numerusform>
            <numerusform>The board's settings differ from the profile in %n places: %1.</numerusform>
        </translation>
    </message>
</context>
</TS>

<?xml version='1.0' encoding='utf-8'?>
<TS version="2.1" language="de_DE">
<context>
    <name>DocumentCommands</name>
    <message>
        <source>Import drawing</source>
        <translation>Zeichnung importieren</translation>
    </message>
    <message>
        <source>Move drawing</source>
        <translation>Zeichnung verschieben</translation>
    </message>
    <message>
        <source>Change working mode</source>
        <translation>Arbeitsmodus ändern</translation>
    </message>
    <message>
        <source>Change machine profile</source>
        <translation>Maschinenprofil ändern</translation>
    </message>
</context>
<context>
    <name>ImportController</name>
    <message>
        <source>Open drawing</source>
        <translation>Zeichnung öffnen</translation>
    </message>
    <message>
        <source>SVG drawings (*.svg);;All files (*)</source>
        <translation>SVG-Zeichnungen (*.svg);;Alle Dateien (*)</translation>
    </message>
    <message>
        <source>%1: another import is still running.</source>
        <translation>%1: Ein anderer Import läuft noch.</translation>
    </message>
    <message>
        <source>Importing %1...</source>
        <translation>%1 wird importiert …</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <source>Import</source>
        <translation>Import</translation>
    </message>
    <message>
        <source>Import of %1 cancelled.</source>
        <translation>Import von %1 abgebrochen.</translation>
    </message>
    <message>
        <source>%1 could not be imported.</source>
        <translation>%1 konnte nicht importiert werden.</translation>
    </message>
    <message>
        <source>Import failed</source>
        <translation>Import fehlgeschlagen</translation>
    </message>
    <message>
        <source>%1 contains nothing to draw.</source>
        <translation>%1 enthält nichts zu zeichnen.</translation>
    </message>
</context>
<context>
    <name>JobPipeline</name>
    <message>
        <source>Nothing to plan: the drawing has no visible path.</source>
        <translation>Nichts zu planen: Die Zeichnung hat keinen sichtbaren Pfad.</translation>
    </message>
    <message>
        <source>The job is not feasible in this working mode.</source>
        <translation>Der Auftrag ist in diesem Arbeitsmodus nicht ausführbar.</translation>
    </message>
    <message>
        <source>No working mode can draw the whole job.</source>
        <translation>Kein Arbeitsmodus kann den ganzen Auftrag zeichnen.</translation>
    </message>
</context>
<context>
    <name>LayersPanel</name>
    <message>
        <source>Plot this layer earlier</source>
        <translation>Diese Ebene früher zeichnen</translation>
    </message>
    <message>
        <source>Plot this layer later</source>
        <translation>Diese Ebene später zeichnen</translation>
    </message>
    <message>
        <source>Tool settings of the selected layer</source>
        <translation>Werkzeugeinstellungen der gewählten Ebene</translation>
    </message>
    <message>
        <source> mm/s</source>
        <translation> mm/s</translation>
    </message>
    <message>
        <source>Profile default</source>
        <translation>Profilvorgabe</translation>
    </message>
    <message>
        <source>Pause before this layer (pen change)</source>
        <translation>Vor dieser Ebene anhalten (Stiftwechsel)</translation>
    </message>
    <message>
        <source>Draw speed:</source>
        <translation>Zeichengeschwindigkeit:</translation>
    </message>
    <message>
        <source>Power / pen S:</source>
        <translation>Leistung / Stift-S:</translation>
    </message>
    <message numerus="yes">
        <source>%n path(s)</source>
        <translation>
            <numerusform>%n Pfad</numerusform><numerusform>%n Pfade</numerusform></translation>
    </message>
    <message numerus="yes">
        <source>%n point(s)</source>
        <translation>
            <numerusform>%n Punkt</numerusform><numerusform>%n Punkte</numerusform></translation>
    </message>
</context>
<context>
    <name>MainWindow</name>
    <message>
        <source>FiveBar Studio</source>
        <translation>FiveBar Studio</translation>
    </message>
    <message>
        <source>x %1 mm, y %2 mm</source>
        <translation>x %1 mm, y %2 mm</translation>
    </message>
    <message>
        <source>Planning...</source>
        <translation>Planung läuft …</translation>
    </message>
    <message>
        <source>Workspace</source>
        <translation>Arbeitsraum</translation>
    </message>
    <message>
        <source>Placement</source>
        <translation>Platzierung</translation>
    </message>
    <message>
        <source>Layers</source>
        <translation>Ebenen</translation>
    </message>
    <message>
        <source>Job preview</source>
        <translation>Auftragsvorschau</translation>
    </message>
    <message>
        <source>Simulation</source>
        <translation>Simulation</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>&amp;Datei</translation>
    </message>
    <message>
        <source>&amp;Open drawing...</source>
        <translation>Zeichnung ö&amp;ffnen …</translation>
    </message>
    <message>
        <source>Open &amp;recent</source>
        <translation>&amp;Zuletzt geöffnet</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>&amp;Beenden</translation>
    </message>
    <message>
        <source>&amp;Edit</source>
        <translation>&amp;Bearbeiten</translation>
    </message>
    <message>
        <source>&amp;Undo</source>
        <translation>&amp;Rückgängig</translation>
    </message>
    <message>
        <source>&amp;Redo</source>
        <translation>&amp;Wiederherstellen</translation>
    </message>
    <message>
        <source>&amp;Fit drawing to workspace</source>
        <translation>Zeichnung in den Arbeitsraum &amp;einpassen</translation>
    </message>
    <message>
        <source>Ctrl+F</source>
        <translation>Ctrl+F</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>&amp;Ansicht</translation>
    </message>
    <message>
        <source>Zoom &amp;in</source>
        <translation>Ver&amp;größern</translation>
    </message>
    <message>
        <source>Ctrl+=</source>
        <translation>Ctrl+=</translation>
    </message>
    <message>
        <source>Zoom &amp;out</source>
        <translation>Ver&amp;kleinern</translation>
    </message>
    <message>
        <source>Zoom to &amp;fit</source>
        <translation>&amp;Alles zeigen</translation>
    </message>
    <message>
        <source>Ctrl+0</source>
        <translation>Ctrl+0</translation>
    </message>
    <message>
        <source>&amp;Simulation</source>
        <translation>&amp;Simulation</translation>
    </message>
    <message>
        <source>&amp;Play / pause</source>
        <translation>&amp;Abspielen / Pause</translation>
    </message>
    <message>
        <source>F5</source>
        <translation>F5</translation>
    </message>
    <message>
        <source>Step &amp;forward</source>
        <translation>Schritt &amp;vor</translation>
    </message>
    <message>
        <source>F6</source>
        <translation>F6</translation>
    </message>
    <message>
        <source>Step &amp;back</source>
        <translation>Schritt &amp;zurück</translation>
    </message>
    <message>
        <source>Shift+F6</source>
        <translation>Shift+F6</translation>
    </message>
    <message>
        <source>&amp;Machine</source>
        <translation>&amp;Maschine</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>&amp;Hilfe</translation>
    </message>
    <message>
        <source>&amp;About FiveBar Studio</source>
        <translation>&amp;Über FiveBar Studio</translation>
    </message>
    <message>
        <source>About FiveBar Studio</source>
        <translation>Über FiveBar Studio</translation>
    </message>
    <message>
        <source>&lt;b&gt;FiveBar Studio %1&lt;/b&gt;&lt;p&gt;Plans and simulates drawings for five-bar linkage robots: workspace and singularity analysis, safe job planning, GRBL output.&lt;/p&gt;</source>
        <translation>&lt;b&gt;FiveBar Studio %1&lt;/b&gt;&lt;p&gt;Plant und simuliert Zeichnungen für Fünfgelenk-Roboter: Arbeitsraum- und Singularitätsanalyse, sichere Auftragsplanung, GRBL-Ausgabe.&lt;/p&gt;</translation>
    </message>
    <message>
        <source>Main</source>
        <translation>Haupt</translation>
    </message>
    <message>
        <source>Clear list</source>
        <translation>Liste leeren</translation>
    </message>
</context>
<context>
    <name>MapPainter</name>
    <message>
        <source>Transmission angle at the pen (deg)</source>
        <translation>Übertragungswinkel am Stift (Grad)</translation>
    </message>
    <message>
        <source>Conditioning (1 = isotropic)</source>
        <translation>Kondition (1 = isotrop)</translation>
    </message>
    <message>
        <source>Resolution (um per motor step)</source>
        <translation>Auflösung (µm je Motorschritt)</translation>
    </message>
</context>
<context>
    <name>ModePanel</name>
    <message>
        <source>Working mode</source>
        <translation>Arbeitsmodus</translation>
    </message>
    <message>
        <source>Auto</source>
        <translation>Auto</translation>
    </message>
    <message>
        <source>Let the planner pick the feasible mode with the largest margin</source>
        <translation>Den Planer den ausführbaren Modus mit dem größten Abstand wählen lassen</translation>
    </message>
    <message>
        <source>Elbows %1 (arm 1 %2, arm 2 %3)</source>
        <translation>Ellbogen %1 (Arm 1 %2, Arm 2 %3)</translation>
    </message>
    <message>
        <source>out</source>
        <translation>außen</translation>
    </message>
    <message>
        <source>in</source>
        <translation>innen</translation>
    </message>
    <message>
        <source>Overlays</source>
        <translation>Überlagerungen</translation>
    </message>
    <message>
        <source>Reachable and singularity-free regions</source>
        <translation>Erreichbare und singularitätsfreie Bereiche</translation>
    </message>
    <message>
        <source>Type II singularity curves</source>
        <translation>Singularitätskurven Typ II</translation>
    </message>
    <message>
        <source>Largest singularity-free rectangle</source>
        <translation>Größtes singularitätsfreies Rechteck</translation>
    </message>
    <message>
        <source>Legend and scale</source>
        <translation>Legende und Maßstab</translation>
    </message>
    <message>
        <source>None</source>
        <translation>Keine</translation>
    </message>
    <message>
        <source>Transmission angle</source>
        <translation>Übertragungswinkel</translation>
    </message>
    <message>
        <source>Conditioning</source>
        <translation>Kondition</translation>
    </message>
    <message>
        <source>Resolution (mm per step)</source>
        <translation>Auflösung (mm je Schritt)</translation>
    </message>
    <message>
        <source>Map:</source>
        <translation>Karte:</translation>
    </message>
    <message>
        <source>Auto picked %1.</source>
        <translation>Auto hat %1 gewählt.</translation>
    </message>
    <message>
        <source>Auto: no mode draws the whole job; showing %1.</source>
        <translation>Auto: Kein Modus zeichnet den ganzen Auftrag; %1 wird gezeigt.</translation>
    </message>
    <message>
        <source>Showing the workspace of %1.</source>
        <translation>Arbeitsraum von %1 wird gezeigt.</translation>
    </message>
    <message>
        <source>Smallest singularity margin: %1 deg.</source>
        <translation>Kleinster Singularitätsabstand: %1 Grad.</translation>
    </message>
</context>
<context>
    <name>PlacementPanel</name>
    <message>
        <source> mm</source>
        <translation> mm</translation>
    </message>
    <message>
        <source> deg</source>
        <translation> Grad</translation>
    </message>
    <message>
        <source> %</source>
        <translation> %</translation>
    </message>
    <message>
        <source>Centre X:</source>
        <translation>Mitte X:</translation>
    </message>
    <message>
        <source>Centre Y:</source>
        <translation>Mitte Y:</translation>
    </message>
    <message>
        <source>Rotation:</source>
        <translation>Drehung:</translation>
    </message>
    <message>
        <source>Scale:</source>
        <translation>Maßstab:</translation>
    </message>
    <message>
        <source>Fit to workspace</source>
        <translation>In Arbeitsraum einpassen</translation>
    </message>
    <message>
        <source>Fit the drawing into the largest singularity-free rectangle</source>
        <translation>Die Zeichnung in das größte singularitätsfreie Rechteck einpassen</translation>
    </message>
</context>
<context>
    <name>PreviewPanel</name>
    <message>
        <source>%1 s</source>
        <translation>%1 s</translation>
    </message>
    <message>
        <source>%1 h %2 min</source>
        <translation>%1 h %2 min</translation>
    </message>
    <message>
        <source>%1 min %2 s</source>
        <translation>%1 min %2 s</translation>
    </message>
    <message>
        <source>Show</source>
        <translation>Anzeigen</translation>
    </message>
    <message>
        <source>Colour pen-down moves by speed</source>
        <translation>Zeichenbewegungen nach Geschwindigkeit färben</translation>
    </message>
    <message>
        <source>Pen-up moves (grey)</source>
        <translation>Leerfahrten (grau)</translation>
    </message>
    <message>
        <source>Drawing order</source>
        <translation>Zeichenreihenfolge</translation>
    </message>
    <message>
        <source>Pre-flight problems (click to show):</source>
        <translation>Probleme der Vorabprüfung (zum Zeigen anklicken):</translation>
    </message>
    <message>
        <source>Moves shown: %1 of %2</source>
        <translation>Gezeigte Bewegungen: %1 von %2</translation>
    </message>
    <message>
        <source>Planning...</source>
        <translation>Planung läuft …</translation>
    </message>
    <message>
        <source>Planned.</source>
        <translation>Geplant.</translation>
    </message>
    <message>
        <source>Open a drawing to plan a job.</source>
        <translation>Öffnen Sie eine Zeichnung, um einen Auftrag zu planen.</translation>
    </message>
    <message>
        <source>&lt;table&gt;&lt;tr&gt;&lt;td&gt;Working mode:&lt;/td&gt;&lt;td&gt;&lt;b&gt;%1&lt;/b&gt;&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;Estimated time:&lt;/td&gt;&lt;td&gt;&lt;b&gt;%2&lt;/b&gt;&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;Pen down:&lt;/td&gt;&lt;td&gt;%3 mm&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;Pen up:&lt;/td&gt;&lt;td&gt;%4 mm&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;Segments:&lt;/td&gt;&lt;td&gt;%5&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;Max deviation:&lt;/td&gt;&lt;td&gt;%6 mm&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;Singularity margin:&lt;/td&gt;&lt;td&gt;%7 deg&lt;/td&gt;&lt;/tr&gt;&lt;/table&gt;</source>
        <translation>&lt;table&gt;&lt;tr&gt;&lt;td&gt;Arbeitsmodus:&lt;/td&gt;&lt;td&gt;&lt;b&gt;%1&lt;/b&gt;&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;Geschätzte Zeit:&lt;/td&gt;&lt;td&gt;&lt;b&gt;%2&lt;/b&gt;&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;Stift unten:&lt;/td&gt;&lt;td&gt;%3 mm&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;Stift oben:&lt;/td&gt;&lt;td&gt;%4 mm&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;Segmente:&lt;/td&gt;&lt;td&gt;%5&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;Größte Abweichung:&lt;/td&gt;&lt;td&gt;%6 mm&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;Singularitätsabstand:&lt;/td&gt;&lt;td&gt;%7 Grad&lt;/td&gt;&lt;/tr&gt;&lt;/table&gt;</translation>
    </message>
    <message>
        <source>Working mode: &lt;b&gt;%1&lt;/b&gt;</source>
        <translation>Arbeitsmodus: &lt;b&gt;%1&lt;/b&gt;</translation>
    </message>
    <message>
        <source>No problems: every move is reachable and safe.</source>
        <translation>Keine Probleme: Jede Bewegung ist erreichbar und sicher.</translation>
    </message>
</context>
<context>
    <name>QObject</name>
    <message>
        <source>Planning failed: %1</source>
        <translation>Planung fehlgeschlagen: %1</translation>
    </message>
</context>
<context>
    <name>SimulationPanel</name>
    <message>
        <source>Step back one move</source>
        <translation>Eine Bewegung zurück</translation>
    </message>
    <message>
        <source>Play / pause the simulation</source>
        <translation>Simulation abspielen / anhalten</translation>
    </message>
    <message>
        <source>Step forward one move</source>
        <translation>Eine Bewegung vor</translation>
    </message>
    <message>
        <source>Simulation speed</source>
        <translation>Simulationsgeschwindigkeit</translation>
    </message>
    <message>
        <source>x%1</source>
        <translation>x%1</translation>
    </message>
    <message>
        <source>No planned job to simulate.</source>
        <translation>Kein geplanter Auftrag zum Simulieren.</translation>
    </message>
    <message>
        <source>%1 of %2</source>
        <translation>%1 von %2</translation>
    </message>
    <message>
        <source>&lt;table&gt;&lt;tr&gt;&lt;td&gt;Motor angles:&lt;/td&gt;&lt;td&gt;%1 deg, %2 deg&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;Pen:&lt;/td&gt;&lt;td&gt;x %3 mm, y %4 mm (%5)&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;Transmission angles:&lt;/td&gt;&lt;td&gt;%6 deg at the pen, %7 / %8 deg at the elbows&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;Type II margin:&lt;/td&gt;&lt;td&gt;&lt;b&gt;%9 deg&lt;/b&gt;&lt;/td&gt;&lt;/tr&gt;&lt;/table&gt;</source>
        <translation>&lt;table&gt;&lt;tr&gt;&lt;td&gt;Motorwinkel:&lt;/td&gt;&lt;td&gt;%1 Grad, %2 Grad&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;Stift:&lt;/td&gt;&lt;td&gt;x %3 mm, y %4 mm (%5)&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;Übertragungswinkel:&lt;/td&gt;&lt;td&gt;%6 Grad am Stift, %7 / %8 Grad an den Ellbogen&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;Abstand Typ II:&lt;/td&gt;&lt;td&gt;&lt;b&gt;%9 Grad&lt;/b&gt;&lt;/td&gt;&lt;/tr&gt;&lt;/table&gt;</translation>
    </message>
    <message>
        <source>down</source>
        <translation>unten</translation>
    </message>
    <message>
        <source>up</source>
        <translation>oben</translation>
    </message>
</context>
<context>
    <name>SpeedLegend</name>
    <message>
        <source>0 mm/s</source>
        <translation>0 mm/s</translation>
    </message>
    <message>
        <source>%1 mm/s</source>
        <translation>%1 mm/s</translation>
    </message>
</context>
<context>
    <name>StudioDocument</name>
    <message>
        <source>Show layer</source>
        <translation>Ebene zeigen</translation>
    </message>
    <message>
        <source>Hide layer</source>
        <translation>Ebene ausblenden</translation>
    </message>
    <message>
        <source>Reorder layers</source>
        <translation>Ebenen umordnen</translation>
    </message>
    <message>
        <source>Change layer tool settings</source>
        <translation>Werkzeugeinstellungen der Ebene ändern</translation>
    </message>
</context>
<context>
    <name>main</name>
    <message>
        <source>Plan and simulate drawings for five-bar robots.</source>
        <translation>Zeichnungen für Fünfgelenk-Roboter planen und simulieren.</translation>
    </message>
    <message>
        <source>Open the demo drawing on the default maker plotter.</source>
        <translation>Die Demo-Zeichnung auf dem Standard-Maker-Plotter öffnen.</translation>
    </message>
    <message>
        <source>Machine profile: a preset name or a profile JSON file.</source>
        <translation>Maschinenprofil: ein Vorgabename oder eine Profil-JSON-Datei.</translation>
    </message>
    <message>
        <source>User interface language (e.g. de, en); default: system.</source>
        <translation>Sprache der Oberfläche (z. B. de, en); Vorgabe: System.</translation>
    </message>
    <message>
        <source>Save a picture of the window once the job is planned, then quit.</source>
        <translation>Ein Bild des Fensters speichern, sobald der Auftrag geplant ist, dann beenden.</translation>
    </message>
    <message>
        <source>SVG drawing to open.</source>
        <translation>Zu öffnende SVG-Zeichnung.</translation>
    </message>
</context>
</TS>
<?xml version='1.0' encoding='utf-8'?>
<!DOCTYPE TS>
<TS version="2.1" language="de_DE">
    <context>
        <name>CalibrationWizard</name>
        <message>
            <source>Hoang's accuracy pattern (10 lines of 40 mm) does not fit in this machine's safe area.</source>
            <translation>Hoangs Genauigkeitsmuster (10 Linien zu 40 mm) passt nicht in den sicheren Bereich dieser Maschine.</translation>
        </message>
        <message>
            <source>The simulated machine drew %1 lines instead of %2.</source>
            <translation>Die simulierte Maschine zeichnete %1 Linien statt %2.</translation>
        </message>
        <message>
            <source>A simulated line is too short to measure.</source>
            <translation>Eine simulierte Linie ist zu kurz zum Messen.</translation>
        </message>
    </context>
    <context>
        <name>Design</name>
        <message>
            <source>%1 must be a positive length in mm</source>
            <translation>%1 muss eine positive Länge in mm sein</translation>
        </message>
        <message>
            <source>the rectangle's width</source>
            <translation>die Breite des Rechtecks</translation>
        </message>
        <message>
            <source>the rectangle's height</source>
            <translation>die Höhe des Rechtecks</translation>
        </message>
        <message>
            <source>the shortest link</source>
            <translation>das kürzeste Glied</translation>
        </message>
        <message>
            <source>the longest link</source>
            <translation>das längste Glied</translation>
        </message>
        <message>
            <source>the shortest link (%1 mm) is longer than the longest (%2 mm)</source>
            <translation>das kürzeste Glied (%1 mm) ist länger als das längste (%2 mm)</translation>
        </message>
        <message>
            <source>the motor spacing must be 0 mm or more</source>
            <translation>der Motorabstand muss 0 mm oder mehr betragen</translation>
        </message>
        <message>
            <source>the smallest motor spacing (%1 mm) exceeds the largest (%2 mm)</source>
            <translation>der kleinste Motorabstand (%1 mm) übersteigt den größten (%2 mm)</translation>
        </message>
        <message>
            <source>the clearance must be 0 mm or more</source>
            <translation>der Sicherheitsabstand muss 0 mm oder mehr betragen</translation>
        </message>
        <message>
            <source>the type II margin must be from 0 to below 90 deg</source>
            <translation>der Typ-II-Abstand muss zwischen 0 und unter 90° liegen</translation>
        </message>
        <message>
            <source>mix weights must be finite and not negative</source>
            <translation>die Gewichte der Mischung müssen endlich und nicht negativ sein</translation>
        </message>
        <message>
            <source>mix weights must not all be zero</source>
            <translation>die Gewichte der Mischung dürfen nicht alle null sein</translation>
        </message>
    </context>
    <context>
        <name>DesignPainter</name>
        <message>
            <source>Workspace, singularity-free region and type II curves</source>
            <translation>Arbeitsraum, singularitätsfreier Bereich und Typ-II-Kurven</translation>
        </message>
        <message>
            <source>a1 = %1, b1 = %2, a2 = %3, b2 = %4, w = %5 mm, working mode %6</source>
            <translation>a1 = %1, b1 = %2, a2 = %3, b2 = %4, w = %5 mm, Arbeitsmodus %6</translation>
        </message>
        <message>
            <source>Rectangle x %1 .. %2, y %3 .. %4 mm; worst condition number %5 (mean %6)</source>
            <translation>Rechteck x %1 .. %2, y %3 .. %4 mm; schlechteste Konditionszahl %5 (Mittel %6)</translation>
        </message>
        <message>
            <source>Type II margin %1 deg, type I margin %2 deg, footprint %3 cm²</source>
            <translation>Abstand zu Typ II %1°, zu Typ I %2°, Platzbedarf %3 cm²</translation>
        </message>
        <message>
            <source>Worst %1 um per step, worst motor speed %2 deg/s</source>
            <translation>Schlechtestens %1 µm pro Schritt, höchste Motordrehzahl %2 °/s</translation>
        </message>
    </context>
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
        <message>
            <source>Rotate drawing</source>
            <translation>Zeichnung drehen</translation>
        </message>
        <message>
            <source>Resize drawing</source>
            <translation>Zeichnungsgröße ändern</translation>
        </message>
    </context>
    <context>
        <name>ImportError</name>
        <message>
            <source>%1 has a point at (%2, %3) mm, beyond the %4 mm limit</source>
            <translation>%1 hat einen Punkt bei (%2, %3) mm, jenseits der Grenze von %4 mm</translation>
        </message>
        <message>
            <source>%1 has a non-finite coordinate</source>
            <translation>%1 hat eine nicht endliche Koordinate</translation>
        </message>
        <message>
            <source>%1 (%2)</source>
            <translation>%1 (%2)</translation>
        </message>
        <message>
            <source>%1: %2</source>
            <translation>%1: %2</translation>
        </message>
        <message>
            <source>%1: nesting deeper than %2 elements</source>
            <translation>%1: tiefer als %2 Elemente verschachtelt</translation>
        </message>
        <message>
            <source>%1: the root element is not &lt;svg&gt;</source>
            <translation>%1: das Wurzelelement ist nicht &lt;svg&gt;</translation>
        </message>
        <message>
            <source>cannot open: %1</source>
            <translation>kann nicht geöffnet werden: %1</translation>
        </message>
        <message>
            <source>cannot read: %1</source>
            <translation>kann nicht gelesen werden: %1</translation>
        </message>
        <message>
            <source>compressed SVG (gzip): %1</source>
            <translation>komprimiertes SVG (gzip): %1</translation>
        </message>
        <message>
            <source>could not create a pipe for the SVG worker: %1</source>
            <translation>keine Pipe für den SVG-Worker: %1</translation>
        </message>
        <message>
            <source>could not start the SVG worker %1: %2</source>
            <translation>der SVG-Worker %1 ließ sich nicht starten: %2</translation>
        </message>
        <message>
            <source>import cancelled</source>
            <translation>Import abgebrochen</translation>
        </message>
        <message>
            <source>layer "%1" has a non-finite coordinate</source>
            <translation>Ebene „%1“ hat eine nicht endliche Koordinate</translation>
        </message>
        <message>
            <source>layer "%1" has a point at (%2, %3) mm, beyond the %4 mm limit</source>
            <translation>Ebene „%1“ hat einen Punkt bei (%2; %3) mm, jenseits der Grenze von %4 mm</translation>
        </message>
        <message>
            <source>line %1, column %2: %3</source>
            <translation>Zeile %1, Spalte %2: %3</translation>
        </message>
        <message>
            <source>line %1: %2</source>
            <translation>Zeile %1: %2</translation>
        </message>
        <message>
            <source>line %1: &lt;%2&gt; attribute %3 contains a value that is not a number (%4)</source>
            <translation>Zeile %1: &lt;%2&gt; Attribut %3 enthält einen Wert, der keine Zahl ist (%4)</translation>
        </message>
        <message>
            <source>line %1: &lt;%2&gt; attribute %3 contains a number beyond 1e300 (%4)</source>
            <translation>Zeile %1: &lt;%2&gt; Attribut %3 enthält eine Zahl über 1e300 (%4)</translation>
        </message>
        <message>
            <source>line %1: &lt;%2&gt;</source>
            <translation>Zeile %1: &lt;%2&gt;</translation>
        </message>
        <message>
            <source>more than %1 points after flattening (the points budget): reading stopped there</source>
            <translation>mehr als %1 Punkte nach dem Glätten (das Punktebudget): das Lesen wurde dort beendet</translation>
        </message>
        <message>
            <source>no &lt;svg&gt; element found</source>
            <translation>kein &lt;svg&gt;-Element gefunden</translation>
        </message>
        <message>
            <source>no such file</source>
            <translation>Datei nicht vorhanden</translation>
        </message>
        <message>
            <source>not readable</source>
            <translation>nicht lesbar</translation>
        </message>
        <message>
            <source>root &lt;svg&gt; %1="%2" is not a length</source>
            <translation>Wurzel-&lt;svg&gt; %1="%2" ist keine Länge</translation>
        </message>
        <message>
            <source>root &lt;svg&gt; %1="%2" is zero or negative: nothing to draw</source>
            <translation>Wurzel-&lt;svg&gt; %1="%2" ist null oder negativ: nichts zu zeichnen</translation>
        </message>
        <message>
            <source>root &lt;svg&gt; viewBox="%1": %2</source>
            <translation>Wurzel-&lt;svg&gt; viewBox="%1": %2</translation>
        </message>
        <message>
            <source>the SVG parser crashed on this file (it is hostile or corrupt, or needed more than the %1 MB memory limit)</source>
            <translation>der SVG-Parser ist an dieser Datei abgestürzt (sie ist bösartig oder beschädigt oder brauchte mehr als die Speichergrenze von %1 MB)</translation>
        </message>
        <message>
            <source>the SVG parser did not finish within %1 s and was stopped (the file is too complex or makes Qt SVG hang)</source>
            <translation>der SVG-Parser wurde nicht innerhalb von %1 s fertig und wurde gestoppt (die Datei ist zu komplex oder lässt Qt SVG hängen)</translation>
        </message>
        <message>
            <source>the SVG worker (fivebar-svg-worker) was not found; set ImportOptions::workerPath or FIVEBAR_SVG_WORKER, or install it next to the program</source>
            <translation>der SVG-Worker (fivebar-svg-worker) wurde nicht gefunden; ImportOptions::workerPath oder FIVEBAR_SVG_WORKER setzen oder ihn neben dem Programm installieren</translation>
        </message>
        <message>
            <source>the SVG worker ended without a readable result (exit code %1): %2</source>
            <translation>der SVG-Worker endete ohne lesbares Ergebnis (Exit-Code %1): %2</translation>
        </message>
        <message>
            <source>the compressed file is empty</source>
            <translation>die komprimierte Datei ist leer</translation>
        </message>
        <message>
            <source>the file is empty</source>
            <translation>die Datei ist leer</translation>
        </message>
    </context>
    <context>
        <name>ImportWarning</name>
        <message>
            <source>text in a single-stroke font: per-glyph x/y/dx/dy lists are not followed, only their first value</source>
            <translation>Text in einer Einstrich-Schrift: Listen von x/y/dx/dy je Zeichen werden nicht befolgt, nur ihr erster Wert</translation>
        </message>
        <message>
            <source>text in a single-stroke font: text on a path (&lt;textPath&gt;) is not drawn</source>
            <translation>Text in einer Einstrich-Schrift: Text auf einem Pfad (&lt;textPath&gt;) wird nicht gezeichnet</translation>
        </message>
        <message>
            <source>text in a single-stroke font: only UTF-8 documents, this one is %1: its text is drawn as outlines</source>
            <translation>Text in einer Einstrich-Schrift: nur UTF-8-Dokumente, dieses ist %1: sein Text wird als Umrisse gezeichnet</translation>
        </message>
        <message>
            <source>clip-path set in a style sheet is not applied: those shapes are drawn unclipped</source>
            <translation>clip-path in einem Stylesheet wird nicht angewandt: diese Formen werden unbeschnitten gezeichnet</translation>
        </message>
        <message>
            <source>%1: its lines there are not drawn</source>
            <translation>%1: seine Linien dort werden nicht gezeichnet</translation>
        </message>
        <message>
            <source>lines outside the page (the SVG viewport) are not drawn: cut at its edge</source>
            <translation>Linien außerhalb der Seite (des SVG-Viewports) werden nicht gezeichnet: an ihrem Rand abgeschnitten</translation>
        </message>
        <message>
            <source>%1: the element is not drawn</source>
            <translation>%1: das Element wird nicht gezeichnet</translation>
        </message>
        <message>
            <source>attribute d: path data begins with "%1", not a moveto (M or m): in error from its first command, nothing drawn</source>
            <translation>Attribut d: die Pfaddaten beginnen mit „%1“, nicht mit einem moveto (M oder m): fehlerhaft ab dem ersten Befehl, nichts gezeichnet</translation>
        </message>
        <message>
            <source>clip-path #%1 not found: drawn unclipped</source>
            <translation>clip-path #%1 nicht gefunden: unbeschnitten gezeichnet</translation>
        </message>
        <message>
            <source>attribute d: invalid path data at character %1 %2: drawn up to the error</source>
            <translation>Attribut d: ungültige Pfaddaten bei Zeichen %1 %2: bis zum Fehler gezeichnet</translation>
        </message>
        <message>
            <source>attribute d: invalid path data at character %1: drawn up to the error</source>
            <translation>Attribut d: ungültige Pfaddaten bei Zeichen %1: bis zum Fehler gezeichnet</translation>
        </message>
        <message>
            <source>transform-origin="%1" not understood: ignored</source>
            <translation>transform-origin="%1" nicht verstanden: ignoriert</translation>
        </message>
        <message>
            <source>marker #%1 not found: not drawn</source>
            <translation>Marker #%1 nicht gefunden: nicht gezeichnet</translation>
        </message>
        <message>
            <source>markers on %1 are not drawn (drawn on path, line, polyline and polygon)</source>
            <translation>Marker an %1 werden nicht gezeichnet (nur an path, line, polyline und polygon)</translation>
        </message>
        <message>
            <source>markers set in a style sheet for the selector '%1' are not drawn (only type, #id and .class selectors are applied)</source>
            <translation>Marker aus einem Stylesheet für den Selektor '%1' werden nicht gezeichnet (nur Typ-, #id- und .class-Selektoren werden angewandt)</translation>
        </message>
        <message>
            <source>external reference removed from %1</source>
            <translation>Externer Verweis aus %1 entfernt</translation>
        </message>
        <message>
            <source>%1 element removed</source>
            <translation>Element %1 entfernt</translation>
        </message>
        <message>
            <source>long &lt;path&gt; split into %1 parts to avoid Qt SVG's 32,767-element truncation</source>
            <translation>Langer &lt;path&gt; in %1 Teile geteilt, um die Kürzung von Qt SVG auf 32.767 Elemente zu vermeiden</translation>
        </message>
        <message>
            <source>further element warnings not listed</source>
            <translation>weitere Warnungen zu Elementen nicht aufgeführt</translation>
        </message>
        <message>
            <source>DOCTYPE with entity declarations removed (internal entities were expanded)</source>
            <translation>DOCTYPE mit Entity-Deklarationen entfernt (interne Entities wurden aufgelöst)</translation>
        </message>
        <message>
            <source>unresolved entity reference dropped</source>
            <translation>nicht auflösbare Entity-Referenz verworfen</translation>
        </message>
        <message>
            <source>external style sheet (xml-stylesheet) ignored</source>
            <translation>externes Stylesheet (xml-stylesheet) ignoriert</translation>
        </message>
        <message>
            <source>event attribute (on...) removed</source>
            <translation>Ereignisattribut (on...) entfernt</translation>
        </message>
        <message>
            <source>CSS @import removed</source>
            <translation>CSS-@import entfernt</translation>
        </message>
        <message>
            <source>transform-origin in a style is not applied</source>
            <translation>transform-origin in einem style wird nicht angewandt</translation>
        </message>
        <message>
            <source>mask not applied: masked shapes are drawn whole</source>
            <translation>mask nicht angewandt: maskierte Formen werden ganz gezeichnet</translation>
        </message>
        <message>
            <source>per-glyph rotate on &lt;text&gt; is not applied: glyphs are drawn upright</source>
            <translation>Drehung einzelner Zeichen (rotate) an &lt;text&gt; wird nicht angewandt: Zeichen werden aufrecht gezeichnet</translation>
        </message>
        <message>
            <source>text on a path (&lt;textPath&gt;) is not drawn</source>
            <translation>Text auf einem Pfad (&lt;textPath&gt;) wird nicht gezeichnet</translation>
        </message>
        <message>
            <source>pattern fills are drawn as outlines, without the pattern</source>
            <translation>Musterfüllungen werden als Umrisse gezeichnet, ohne das Muster</translation>
        </message>
        <message>
            <source>more than 100000 marker instances: the rest are not drawn</source>
            <translation>mehr als 100000 Marker: der Rest wird nicht gezeichnet</translation>
        </message>
        <message>
            <source>marker overflow clipping not applied: marker content is drawn whole</source>
            <translation>Marker-Beschnitt (overflow) nicht angewandt: der Inhalt wird ganz gezeichnet</translation>
        </message>
        <message>
            <source>no usable width/height/viewBox: page size taken from the drawing's extent</source>
            <translation>keine brauchbare width/height/viewBox: Seitengröße aus der Ausdehnung der Zeichnung</translation>
        </message>
        <message>
            <source>line %1: %2 %3</source>
            <translation>Zeile %1: %2 %3</translation>
        </message>
        <message>
            <source>%1 (%2x, first at line %3)</source>
            <translation>%1 (%2x, zuerst in Zeile %3)</translation>
        </message>
    </context>
    <context>
        <name>ImportWarningsPanel</name>
        <message>
            <source>%1 has %2 points after flattening, more than the budget of %3 (a runaway file?).</source>
            <translation>%1 hat nach dem Glätten %2 Punkte, mehr als das Budget von %3 (eine außer Kontrolle geratene Datei?).</translation>
        </message>
        <message>
            <source>Very large drawing</source>
            <translation>Sehr große Zeichnung</translation>
        </message>
        <message>
            <source>Planning and plotting it may take very long. Import it anyway?</source>
            <translation>Planen und Zeichnen können sehr lange dauern. Trotzdem importieren?</translation>
        </message>
    </context>
    <context>
        <name>JobPipeline</name>
        <message>
            <source>Nothing to plan: the drawing has no visible path.</source>
            <translation>Nichts zu planen: Die Zeichnung hat keinen sichtbaren Pfad.</translation>
        </message>
        <message>
            <source>Planning cancelled.</source>
            <translation>Planung abgebrochen.</translation>
        </message>
        <message>
            <source>Planned in working mode %1.</source>
            <translation>Geplant im Arbeitsmodus %1.</translation>
        </message>
        <message>
            <source>This job is long: about %1 hours and %2 pen-down moves. The machine will be busy all that time. Start it anyway?</source>
            <translation>Dieser Auftrag ist lang: etwa %1 Stunden und %2 Zeichenbewegungen. Die Maschine ist die ganze Zeit beschäftigt. Trotzdem starten?</translation>
        </message>
        <message>
            <source>%1: %2</source>
            <translation>%1: %2</translation>
        </message>
        <message>
            <source>%1: cannot write a temporary copy to import</source>
            <translation>%1: keine temporäre Kopie zum Importieren möglich</translation>
        </message>
        <message>
            <source>%1: cannot be imported</source>
            <translation>%1: kann nicht importiert werden</translation>
        </message>
        <message>
            <source>%1: cannot read (%2)</source>
            <translation>%1: kann nicht gelesen werden (%2)</translation>
        </message>
        <message>
            <source>no machine profile given</source>
            <translation>kein Maschinenprofil angegeben</translation>
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
        <name>Placement</name>
        <message>
            <source>scaled to %1 % to fit the workspace</source>
            <translation>auf %1 % verkleinert, damit sie in den Arbeitsraum passt</translation>
        </message>
    </context>
    <context>
        <name>Planner</name>
        <message>
            <source>layer '%1'</source>
            <translation>Ebene '%1'</translation>
        </message>
        <message>
            <source>layer %1</source>
            <translation>Ebene %1</translation>
        </message>
        <message>
            <source>move or shrink the drawing (--at, --scale, --fit)</source>
            <translation>Zeichnung verschieben oder verkleinern (--at, --scale, --fit)</translation>
        </message>
        <message>
            <source>try another working mode (--mode)</source>
            <translation>einen anderen Arbeitsmodus versuchen (--mode)</translation>
        </message>
        <message>
            <source>travel back to the start pose</source>
            <translation>Rückfahrt zur Startstellung</translation>
        </message>
        <message>
            <source>start pose</source>
            <translation>Startstellung</translation>
        </message>
        <message>
            <source>the profile's home pose does not close the linkage</source>
            <translation>die Grundstellung des Profils schließt das Getriebe nicht</translation>
        </message>
        <message>
            <source>set a reachable home pose in the profile</source>
            <translation>eine erreichbare Grundstellung im Profil einstellen</translation>
        </message>
        <message>
            <source>a point is out of reach in working mode %1</source>
            <translation>ein Punkt ist im Arbeitsmodus %1 außer Reichweite</translation>
        </message>
        <message>
            <source>the drawn curve cannot follow the stroke here (singular region)</source>
            <translation>die gezeichnete Kurve kann dem Strich hier nicht folgen (singulärer Bereich)</translation>
        </message>
        <message>
            <source>the drawn line %1</source>
            <translation>die gezeichnete Linie %1</translation>
        </message>
        <message>
            <source>travel to %1</source>
            <translation>Fahrt zu %1</translation>
        </message>
        <message>
            <source>no safe pen-up travel reaches it</source>
            <translation>keine sichere Fahrt mit angehobenem Stift erreicht ihn</translation>
        </message>
        <message>
            <source>move the drawing away from singular regions (--at)</source>
            <translation>die Zeichnung von singulären Bereichen wegschieben (--at)</translation>
        </message>
        <message>
            <source>try another --mode</source>
            <translation>einen anderen --mode versuchen</translation>
        </message>
        <message>
            <source>%1 path %2</source>
            <translation>%1 Pfad %2</translation>
        </message>
        <message>
            <source>tolerance %1 mm leaves nothing for the moves after flattening (%2 mm) and the G-code rounding (up to %3 mm)</source>
            <translation>die Toleranz von %1 mm lässt nach der Kurvennäherung (%2 mm) und der G-Code-Rundung (bis %3 mm) nichts für die Bewegungen übrig</translation>
        </message>
        <message>
            <source>backlash compensation</source>
            <translation>Spielausgleich</translation>
        </message>
        <message>
            <source>move the drawing away from the workspace edge (--at)</source>
            <translation>die Zeichnung vom Rand des Arbeitsraums wegschieben (--at)</translation>
        </message>
        <message>
            <source>planning cancelled</source>
            <translation>Planung abgebrochen</translation>
        </message>
        <message>
            <source>%1: %2</source>
            <translation>%1: %2</translation>
        </message>
        <message>
            <source>backlash compensation: a compensated move %1</source>
            <translation>Spielausgleich: eine ausgeglichene Bewegung %1</translation>
        </message>
        <message>
            <source>shrink the drawing to %1 % (--scale %2)</source>
            <translation>die Zeichnung auf %1 % verkleinern (--scale %2)</translation>
        </message>
        <message>
            <source>move the drawing's centre to x %1 mm, y %2 mm (--at %3,%4)</source>
            <translation>die Mitte der Zeichnung nach x %1 mm, y %2 mm verschieben (--at %3,%4)</translation>
        </message>
        <message>
            <source>use working mode %1 (--mode %1)</source>
            <translation>Arbeitsmodus %1 verwenden (--mode %1)</translation>
        </message>
        <message>
            <source>fit the drawing into the workspace (--fit)</source>
            <translation>die Zeichnung in den Arbeitsraum einpassen (--fit)</translation>
        </message>
        <message>
            <source>job</source>
            <translation>Auftrag</translation>
        </message>
        <message>
            <source>working mode %1: %2: %3</source>
            <translation>Arbeitsmodus %1: %2: %3</translation>
        </message>
        <message>
            <source>scale must be a positive number</source>
            <translation>der Maßstab muss eine positive Zahl sein</translation>
        </message>
        <message>
            <source>nothing visible to draw in '%1'</source>
            <translation>nichts Sichtbares zu zeichnen in '%1'</translation>
        </message>
        <message>
            <source>no working mode has a singularity-free area to place the drawing in</source>
            <translation>kein Arbeitsmodus hat einen singularitätsfreien Bereich, in den die Zeichnung passt</translation>
        </message>
        <message>
            <source>check the profile</source>
            <translation>das Profil prüfen</translation>
        </message>
        <message>
            <source>the drawing was flattened within %1 mm, too coarse at %2 %: import it again within %3 mm</source>
            <translation>die Zeichnung wurde auf %1 mm genau angenähert, zu grob bei %2 %: erneut auf %3 mm genau importieren</translation>
        </message>
        <message>
            <source>move or shrink the drawing in the Placement panel</source>
            <translation>die Zeichnung im Bereich Platzierung verschieben oder verkleinern</translation>
        </message>
        <message>
            <source>try another working mode in the Workspace panel</source>
            <translation>im Bereich Arbeitsraum einen anderen Arbeitsmodus versuchen</translation>
        </message>
        <message>
            <source>move the drawing away from singular regions in the Placement panel</source>
            <translation>die Zeichnung im Bereich Platzierung von singulären Bereichen wegschieben</translation>
        </message>
        <message>
            <source>move the drawing away from the workspace edge in the Placement panel</source>
            <translation>die Zeichnung im Bereich Platzierung vom Rand des Arbeitsraums wegschieben</translation>
        </message>
        <message>
            <source>set Scale to %1 % in the Placement panel</source>
            <translation>im Bereich Platzierung „Maßstab“ auf %1 % setzen</translation>
        </message>
        <message>
            <source>set Centre X to %1 mm and Centre Y to %2 mm in the Placement panel</source>
            <translation>im Bereich Platzierung „Mitte X“ auf %1 mm und „Mitte Y“ auf %2 mm setzen</translation>
        </message>
        <message>
            <source>choose working mode %1 in the Workspace panel</source>
            <translation>im Bereich Arbeitsraum den Arbeitsmodus %1 wählen</translation>
        </message>
        <message>
            <source>press Fit to workspace in the Placement panel</source>
            <translation>im Bereich Platzierung auf „In Arbeitsraum einpassen“ klicken</translation>
        </message>
    </context>
    <context>
        <name>Preflight</name>
        <message>
            <source>layer %1 path %2 point %3 at (%4, %5) mm</source>
            <translation>Ebene %1 Pfad %2 Punkt %3 bei (%4; %5) mm</translation>
        </message>
        <message>
            <source>%1 is out of reach of leg %2</source>
            <translation>%1 ist außerhalb der Reichweite von Arm %2</translation>
        </message>
        <message>
            <source>%1 needs assembly mode %2 in working mode %3</source>
            <translation>%1 braucht Montagemodus %2 im Arbeitsmodus %3</translation>
        </message>
        <message>
            <source>%1: %2</source>
            <translation>%1: %2</translation>
        </message>
        <message>
            <source>the line to %1 %2</source>
            <translation>die Linie zu %1 %2</translation>
        </message>
        <message>
            <source>the travel back to the home pose</source>
            <translation>die Rückfahrt zur Grundstellung</translation>
        </message>
        <message>
            <source>the travel to %1</source>
            <translation>die Fahrt zu %1</translation>
        </message>
        <message>
            <source>%1 %2</source>
            <translation>%1 %2</translation>
        </message>
        <message>
            <source>%1; no safe detour found</source>
            <translation>%1; kein sicherer Umweg gefunden</translation>
        </message>
        <message>
            <source>%1; detour not searched (limit of searches per job reached)</source>
            <translation>%1; kein Umweg gesucht (Grenze der Suchen je Auftrag erreicht)</translation>
        </message>
        <message>
            <source>mode %1: feasible, worst type II margin %2 deg</source>
            <translation>Modus %1: machbar, kleinster Abstand zu Typ II %2°</translation>
        </message>
        <message>
            <source>mode %1: 1 problem</source>
            <translation>Modus %1: 1 Problem</translation>
        </message>
        <message>
            <source>mode %1: %2 problems</source>
            <translation>Modus %1: %2 Probleme</translation>
        </message>
        <message>
            <source>%1 (first: %2)</source>
            <translation>%1 (erstes: %2)</translation>
        </message>
        <message>
            <source>%1; fix: shrink to %2%</source>
            <translation>%1; Abhilfe: auf %2 % verkleinern</translation>
        </message>
        <message>
            <source>%1; fix: move the centre to (%2, %3) mm</source>
            <translation>%1; Abhilfe: die Mitte nach (%2; %3) mm verschieben</translation>
        </message>
        <message>
            <source>point %1 at (%2, %3) mm</source>
            <translation>Punkt %1 bei (%2; %3) mm</translation>
        </message>
    </context>
    <context>
        <name>QObject</name>
        <message>
            <source>Planning failed: %1</source>
            <translation>Planung fehlgeschlagen: %1</translation>
        </message>
        <message>
            <source>Cannot write %1: %2</source>
            <translation>%1 kann nicht geschrieben werden: %2</translation>
        </message>
    </context>
    <context>
        <name>Safety</name>
        <message>
            <source>safe; closest approach to a type II singularity %1 deg</source>
            <translation>sicher; kleinster Abstand zu einer Typ-II-Singularität %1°</translation>
        </message>
        <message>
            <source>passes within %1 deg of a type II singularity at (%2, %3) mm, %4% along the move</source>
            <translation>kommt einer Typ-II-Singularität bis auf %1° nahe bei (%2; %3) mm, nach %4 % der Bewegung</translation>
        </message>
        <message>
            <source>a leg comes too close to full stretch or fold (type I) at (%1, %2) mm, %3% along the move</source>
            <translation>ein Arm kommt der vollen Streckung oder Faltung zu nahe (Typ I) bei (%1; %2) mm, nach %3 % der Bewegung</translation>
        </message>
        <message>
            <source>goes beyond a motor's joint limit at (%1, %2) mm, %3% along the move</source>
            <translation>überschreitet die Gelenkgrenze eines Motors bei (%1; %2) mm, nach %3 % der Bewegung</translation>
        </message>
        <message>
            <source>leaves the reachable workspace (the linkage cannot close) at (%1, %2) mm, %3% along the move</source>
            <translation>verlässt den erreichbaren Arbeitsraum (das Getriebe kann nicht schließen) bei (%1; %2) mm, nach %3 % der Bewegung</translation>
        </message>
        <message>
            <source>passes through a type II singularity, where the assembly mode can flip at (%1, %2) mm, %3% along the move</source>
            <translation>durchläuft eine Typ-II-Singularität, wo der Montagemodus umschlagen kann, bei (%1; %2) mm, nach %3 % der Bewegung</translation>
        </message>
        <message>
            <source>unknown move status</source>
            <translation>unbekannter Bewegungsstatus</translation>
        </message>
    </context>
    <context>
        <name>WorkspaceLegend</name>
        <message>
            <source>type II &gt;= %1 deg, type I &gt;= %2 deg</source>
            <translation>Typ II &gt;= %1°, Typ I &gt;= %2°</translation>
        </message>
        <message>
            <source>none</source>
            <translation>keins</translation>
        </message>
        <message>
            <source>singularity-free (%1)</source>
            <translation>singularitätsfrei (%1)</translation>
        </message>
        <message>
            <source>reachable, within a singularity margin</source>
            <translation>erreichbar, innerhalb eines Singularitätsabstands</translation>
        </message>
        <message>
            <source>reach boundary</source>
            <translation>Reichweitengrenze</translation>
        </message>
        <message>
            <source>singularity-free boundary</source>
            <translation>Grenze des singularitätsfreien Bereichs</translation>
        </message>
        <message>
            <source>type II singularity (%1 curves)</source>
            <translation>Typ-II-Singularität (%1 Kurven)</translation>
        </message>
        <message>
            <source>largest rectangle: %1</source>
            <translation>größtes Rechteck: %1</translation>
        </message>
        <message>
            <source>reachable area: %1 cm²</source>
            <translation>erreichbare Fläche: %1 cm²</translation>
        </message>
        <message>
            <source>singularity-free area: %1 cm²</source>
            <translation>singularitätsfreie Fläche: %1 cm²</translation>
        </message>
    </context>
    <context>
        <name>fivebar::studio::FileActions</name>
        <message>
            <source>Unsaved changes</source>
            <translation>Ungespeicherte Änderungen</translation>
        </message>
        <message>
            <source>%1 has changes that are not saved. Save them first?</source>
            <translation>%1 hat ungespeicherte Änderungen. Zuerst speichern?</translation>
        </message>
        <message>
            <source>Cannot save %1: %2</source>
            <translation>%1 kann nicht gespeichert werden: %2</translation>
        </message>
        <message>
            <source>Nothing to save: open a drawing first.</source>
            <translation>Nichts zu speichern: zuerst eine Zeichnung öffnen.</translation>
        </message>
        <message>
            <source>Save failed</source>
            <translation>Speichern fehlgeschlagen</translation>
        </message>
        <message>
            <source>Saved %1</source>
            <translation>%1 gespeichert</translation>
        </message>
        <message>
            <source>Save project</source>
            <translation>Projekt speichern</translation>
        </message>
        <message>
            <source>FiveBar projects (*.fivebar)</source>
            <translation>FiveBar-Projekte (*.fivebar)</translation>
        </message>
        <message>
            <source>The job is still being planned; export it when planning is done.</source>
            <translation>Der Auftrag wird noch geplant; exportieren Sie ihn, wenn die Planung fertig ist.</translation>
        </message>
        <message>
            <source>There is no planned job to export (see the job preview).</source>
            <translation>Es gibt keinen geplanten Auftrag zum Exportieren (siehe Auftragsvorschau).</translation>
        </message>
        <message>
            <source>Cannot write %1: %2</source>
            <translation>%1 kann nicht geschrieben werden: %2</translation>
        </message>
        <message>
            <source>Export G-code</source>
            <translation>G-Code exportieren</translation>
        </message>
        <message>
            <source>G-code (*.gcode *.nc);;All files (*)</source>
            <translation>G-Code (*.gcode *.nc);;Alle Dateien (*)</translation>
        </message>
        <message>
            <source>Exported %1</source>
            <translation>%1 exportiert</translation>
        </message>
        <message>
            <source>Clear list</source>
            <translation>Liste leeren</translation>
        </message>
        <message>
            <source>The untitled project made from %1 has changes that are not saved. Save it as a project first?</source>
            <translation>Das unbenannte Projekt aus %1 hat ungespeicherte Änderungen. Zuerst als Projekt speichern?</translation>
        </message>
    </context>
    <context>
        <name>fivebar::studio::LanguageMenu</name>
        <message>
            <source>&amp;Language</source>
            <translation>&amp;Sprache</translation>
        </message>
        <message>
            <source>System default</source>
            <translation>Systemvorgabe</translation>
        </message>
        <message>
            <source>Language</source>
            <translation>Sprache</translation>
        </message>
        <message>
            <source>The new language applies when FiveBar Studio starts again.</source>
            <translation>Die neue Sprache gilt, sobald FiveBar Studio neu gestartet wird.</translation>
        </message>
    </context>
    <context>
        <name>fivebar::studio::MainWindow</name>
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
            <source>&amp;Open drawing or project...</source>
            <translation>Zeichnung oder Projekt &amp;öffnen...</translation>
        </message>
        <message>
            <source>&amp;Save project</source>
            <translation>Projekt &amp;speichern</translation>
        </message>
        <message>
            <source>Save project &amp;as...</source>
            <translation>Projekt speichern &amp;unter...</translation>
        </message>
        <message>
            <source>&amp;Export G-code...</source>
            <translation>G-Code &amp;exportieren...</translation>
        </message>
        <message>
            <source>Ctrl+E</source>
            <translation>Ctrl+E</translation>
        </message>
        <message>
            <source>&amp;Actual size (100 %)</source>
            <translation>&amp;Originalgröße (100 %)</translation>
        </message>
        <message>
            <source>Ctrl+1</source>
            <translation>Ctrl+1</translation>
        </message>
        <message>
            <source>%1[*] - FiveBar Studio</source>
            <translation>%1[*] - FiveBar Studio</translation>
        </message>
        <message>
            <source>Fills</source>
            <translation>Füllungen</translation>
        </message>
        <message>
            <source>Import warnings</source>
            <translation>Importwarnungen</translation>
        </message>
        <message>
            <source>Untitled project (%1)[*] - FiveBar Studio</source>
            <translation>Unbenanntes Projekt (%1)[*] - FiveBar Studio</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::ConsolePanel</name>
        <message>
            <source>Lines sent to and received from the machine appear here.</source>
            <translation>Hier erscheinen die an die Maschine gesendeten und von ihr empfangenen Zeilen.</translation>
        </message>
        <message>
            <source>Send</source>
            <translation>Senden</translation>
        </message>
        <message>
            <source>G-code or $ command, e.g. $$ or $I; moves are checked first</source>
            <translation>G-Code oder $-Befehl, z. B. $$ oder $I; Bewegungen werden zuerst geprüft</translation>
        </message>
        <message>
            <source>Send unchecked (expert)</source>
            <translation>Ungeprüft senden (Experten)</translation>
        </message>
        <message>
            <source>Send lines without the motion check. X and Y are motor angles in degrees: a wrong number swings an arm across the base.</source>
            <translation>Zeilen ohne Bewegungsprüfung senden. X und Y sind Motorwinkel in Grad: Eine falsche Zahl schwenkt einen Arm quer über die Basis.</translation>
        </message>
        <message>
            <source>Unchecked console: lines go to the machine as typed, without the motion check. A wrong X or Y (motor angles in degrees) can drive the arms into each other or the base.</source>
            <translation>Ungeprüfte Konsole: Zeilen gehen so an die Maschine, wie sie getippt wurden, ohne Bewegungsprüfung. Ein falsches X oder Y (Motorwinkel in Grad) kann die Arme ineinander oder in die Basis fahren.</translation>
        </message>
        <message>
            <source>Not sent: %1</source>
            <translation>Nicht gesendet: %1</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::DesignDialog</name>
        <message>
            <source>Design a machine</source>
            <translation>Maschine entwerfen</translation>
        </message>
        <message>
            <source>&amp;Design...</source>
            <translation>&amp;Entwurf...</translation>
        </message>
        <message>
            <source>Choose link lengths for a paper size</source>
            <translation>Gliedlängen für ein Papierformat wählen</translation>
        </message>
        <message>
            <source>Brief</source>
            <translation>Vorgaben</translation>
        </message>
        <message>
            <source>Custom</source>
            <translation>Eigenes Format</translation>
        </message>
        <message>
            <source>Landscape</source>
            <translation>Querformat</translation>
        </message>
        <message>
            <source>Portrait</source>
            <translation>Hochformat</translation>
        </message>
        <message>
            <source> mm</source>
            <translation> mm</translation>
        </message>
        <message>
            <source> deg</source>
            <translation> °</translation>
        </message>
        <message>
            <source>Symmetric arms</source>
            <translation>Symmetrische Arme</translation>
        </message>
        <message>
            <source>Any</source>
            <translation>Beliebig</translation>
        </message>
        <message>
            <source>Worst condition number</source>
            <translation>Schlechteste Konditionszahl</translation>
        </message>
        <message>
            <source>Worst resolution</source>
            <translation>Schlechteste Auflösung</translation>
        </message>
        <message>
            <source>Footprint</source>
            <translation>Platzbedarf</translation>
        </message>
        <message>
            <source>Weighted mix</source>
            <translation>Gewichtete Mischung</translation>
        </message>
        <message>
            <source>Condition</source>
            <translation>Kondition</translation>
        </message>
        <message>
            <source>Resolution</source>
            <translation>Auflösung</translation>
        </message>
        <message>
            <source>Weight of this normalised term in the weighted mix</source>
            <translation>Gewicht dieses normierten Terms in der gewichteten Mischung</translation>
        </message>
        <message>
            <source>Mix weights</source>
            <translation>Gewichte der Mischung</translation>
        </message>
        <message>
            <source>Paper</source>
            <translation>Papier</translation>
        </message>
        <message>
            <source>Orientation</source>
            <translation>Ausrichtung</translation>
        </message>
        <message>
            <source>Width</source>
            <translation>Breite</translation>
        </message>
        <message>
            <source>Height</source>
            <translation>Höhe</translation>
        </message>
        <message>
            <source>Margin</source>
            <translation>Rand</translation>
        </message>
        <message>
            <source>Shortest link</source>
            <translation>Kürzestes Glied</translation>
        </message>
        <message>
            <source>Longest link</source>
            <translation>Längstes Glied</translation>
        </message>
        <message>
            <source>Smallest motor spacing</source>
            <translation>Kleinster Motorabstand</translation>
        </message>
        <message>
            <source>Largest motor spacing</source>
            <translation>Größter Motorabstand</translation>
        </message>
        <message>
            <source>Arm clearance</source>
            <translation>Armabstand</translation>
        </message>
        <message>
            <source>Type II margin</source>
            <translation>Abstand zu Typ-II-Singularitäten</translation>
        </message>
        <message>
            <source>Working mode</source>
            <translation>Arbeitsmodus</translation>
        </message>
        <message>
            <source>Objective</source>
            <translation>Ziel</translation>
        </message>
        <message>
            <source>Search</source>
            <translation>Suchen</translation>
        </message>
        <message>
            <source>Cancel</source>
            <translation>Abbrechen</translation>
        </message>
        <message>
            <source>Set the brief and press Search.</source>
            <translation>Vorgaben einstellen und Suchen drücken.</translation>
        </message>
        <message>
            <source>Worst condition</source>
            <translation>Schlechteste Kondition</translation>
        </message>
        <message>
            <source>Footprint (cm²)</source>
            <translation>Platzbedarf (cm²)</translation>
        </message>
        <message>
            <source>µm/step</source>
            <translation>µm/Schritt</translation>
        </message>
        <message>
            <source>Mode</source>
            <translation>Modus</translation>
        </message>
        <message>
            <source>Workspace</source>
            <translation>Arbeitsraum</translation>
        </message>
        <message>
            <source>Conditioning</source>
            <translation>Kondition</translation>
        </message>
        <message>
            <source>Transmission angle</source>
            <translation>Übertragungswinkel</translation>
        </message>
        <message>
            <source>Map on the canvas</source>
            <translation>Karte auf der Zeichenfläche</translation>
        </message>
        <message>
            <source>Use as profile</source>
            <translation>Als Profil verwenden</translation>
        </message>
        <message>
            <source>Export...</source>
            <translation>Exportieren...</translation>
        </message>
        <message>
            <source>Searching...</source>
            <translation>Suche läuft...</translation>
        </message>
        <message>
            <source>Search cancelled.</source>
            <translation>Suche abgebrochen.</translation>
        </message>
        <message>
            <source>No design meets the brief: %1</source>
            <translation>Kein Entwurf erfüllt die Vorgaben: %1</translation>
        </message>
        <message>
            <source>Best worst-case condition number %1; %2 designs on the trade-off, %3 evaluations in %4 s.</source>
            <translation>Beste Konditionszahl im schlechtesten Fall %1; %2 Entwürfe im Zielkonflikt, %3 Auswertungen in %4 s.</translation>
        </message>
        <message>
            <source>The document now uses this design (Edit &gt; Undo restores the previous profile).</source>
            <translation>Das Dokument verwendet jetzt diesen Entwurf (Bearbeiten &gt; Rückgängig stellt das vorige Profil wieder her).</translation>
        </message>
        <message>
            <source>No design is selected.</source>
            <translation>Kein Entwurf ausgewählt.</translation>
        </message>
        <message>
            <source>Export profile</source>
            <translation>Profil exportieren</translation>
        </message>
        <message>
            <source>Machine profiles (*.json)</source>
            <translation>Maschinenprofile (*.json)</translation>
        </message>
        <message>
            <source>Profile written to %1.</source>
            <translation>Profil nach %1 geschrieben.</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::FillOptionsBox</name>
        <message>
            <source>Draw dashed strokes solid</source>
            <translation>Gestrichelte Linien durchgehend zeichnen</translation>
        </message>
        <message>
            <source>Dashed strokes are drawn as their dashes, the pen lifted between them; checked: each dashed stroke is drawn as one line.</source>
            <translation>Gestrichelte Linien werden als ihre Striche gezeichnet, dazwischen wird der Stift gehoben; angekreuzt: jede gestrichelte Linie wird als eine Linie gezeichnet.</translation>
        </message>
        <message>
            <source>Filled shapes</source>
            <translation>Gefüllte Formen</translation>
        </message>
        <message>
            <source>Outline</source>
            <translation>Umriss</translation>
        </message>
        <message>
            <source>Hatch</source>
            <translation>Schraffur</translation>
        </message>
        <message>
            <source>Not drawn</source>
            <translation>Nicht zeichnen</translation>
        </message>
        <message>
            <source>Outline: the shape's edge (as AxiDraw and vpype draw fills). Hatch: parallel lines inside the shape. Not drawn: fill-only shapes are left out.</source>
            <translation>Umriss: der Rand der Form (wie AxiDraw und vpype Füllungen zeichnen). Schraffur: parallele Linien in der Form. Nicht zeichnen: nur gefüllte Formen entfallen.</translation>
        </message>
        <message>
            <source> mm</source>
            <translation> mm</translation>
        </message>
        <message>
            <source> deg</source>
            <translation> Grad</translation>
        </message>
        <message>
            <source>Crosshatch</source>
            <translation>Kreuzschraffur</translation>
        </message>
        <message>
            <source>Keep the outline</source>
            <translation>Umriss behalten</translation>
        </message>
        <message>
            <source>Import again with these settings</source>
            <translation>Mit diesen Einstellungen neu importieren</translation>
        </message>
        <message>
            <source>Fill:</source>
            <translation>Füllung:</translation>
        </message>
        <message>
            <source>Line spacing:</source>
            <translation>Linienabstand:</translation>
        </message>
        <message>
            <source>Angle:</source>
            <translation>Winkel:</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::GoToTool</name>
        <message>
            <source>Connect the machine first: its position is not known.</source>
            <translation>Verbinden Sie zuerst die Maschine: ihre Position ist nicht bekannt.</translation>
        </message>
        <message>
            <source>Cannot go there: %1</source>
            <translation>Dorthin kann nicht gefahren werden: %1</translation>
        </message>
        <message numerus="yes">
            <source>Go to %1, %2 mm? The dashed path is the pen's travel (%n checked move(s)).</source>
            <translation>
                <numerusform>Nach %1, %2 mm fahren? Der gestrichelte Weg ist die Fahrt des Stifts (%n geprüfte Bewegung).</numerusform>
                <numerusform>Nach %1, %2 mm fahren? Der gestrichelte Weg ist die Fahrt des Stifts (%n geprüfte Bewegungen).</numerusform>
            </translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::ImportController</name>
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
        <message>
            <source>Open drawing or project</source>
            <translation>Zeichnung oder Projekt öffnen</translation>
        </message>
        <message>
            <source>Drawings and projects (*.svg *.fivebar);;SVG drawings (*.svg);;FiveBar projects (*.fivebar);;All files (*)</source>
            <translation>Zeichnungen und Projekte (*.svg *.fivebar);;SVG-Zeichnungen (*.svg);;FiveBar-Projekte (*.fivebar);;Alle Dateien (*)</translation>
        </message>
        <message>
            <source>Very large drawing</source>
            <translation>Sehr große Zeichnung</translation>
        </message>
        <message>
            <source>%1 has more than %2 points after flattening (a runaway file?). Reading it was stopped there.

Planning and plotting it may take very long. Import it whole anyway?</source>
            <translation>%1 hat nach dem Glätten mehr als %2 Punkte (eine außer Kontrolle geratene Datei?). Das Einlesen wurde dort angehalten.

Planen und Zeichnen können sehr lange dauern. Trotzdem ganz importieren?</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::ImportWarningsPanel</name>
        <message>
            <source>No drawing imported yet.</source>
            <translation>Noch keine Zeichnung importiert.</translation>
        </message>
        <message>
            <source>What the importer dropped, approximated or could not draw. docs/svg-import.md lists what is supported.</source>
            <translation>Was der Import weggelassen, angenähert oder nicht zeichnen konnte. docs/svg-import.md listet, was unterstützt wird.</translation>
        </message>
        <message>
            <source>%1 imported without warnings.</source>
            <translation>%1 ohne Warnungen importiert.</translation>
        </message>
        <message>
            <source>1 warning while importing %1: part of the drawing may differ from what a browser shows.</source>
            <translation>1 Warnung beim Import von %1: ein Teil der Zeichnung kann von der Anzeige im Browser abweichen.</translation>
        </message>
        <message>
            <source>%1 warnings while importing %2: parts of the drawing may differ from what a browser shows.</source>
            <translation>%1 Warnungen beim Import von %2: Teile der Zeichnung können von der Anzeige im Browser abweichen.</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::JobLayer</name>
        <message>
            <source>Planning...</source>
            <translation>Planung läuft...</translation>
        </message>
    </context>
    <context>
        <name>fivebar::session::JogController</name>
        <message>
            <source>Jog refused: the machine is not connected, not idle, or a job is running.</source>
            <translation>Verfahren abgelehnt: Die Maschine ist nicht verbunden, nicht bereit, oder ein Auftrag läuft.</translation>
        </message>
        <message>
            <source>Jog stopped at the last safe point: %1</source>
            <translation>Verfahren am letzten sicheren Punkt angehalten: %1</translation>
        </message>
        <message>
            <source>Jog refused: %1</source>
            <translation>Verfahren abgelehnt: %1</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::JogPanel</name>
        <message>
            <source>Frame the job</source>
            <translation>Auftrag umfahren</translation>
        </message>
        <message>
            <source>Trace the outline of the planned job with the pen up (a laser at low power), along checked moves, to see where the drawing lands on the paper</source>
            <translation>Den Umriss des geplanten Auftrags mit angehobenem Stift (ein Laser mit geringer Leistung) auf geprüften Bewegungen abfahren, um zu sehen, wo die Zeichnung auf dem Papier landet</translation>
        </message>
        <message>
            <source>Tracing the job's outline with the pen up.</source>
            <translation>Der Umriss des Auftrags wird mit angehobenem Stift abgefahren.</translation>
        </message>
        <message>
            <source>Jog the pen %1 mm in X, %2 mm in Y per step; hold for a continuous jog</source>
            <translation>Stift pro Schritt um %1 mm in X und %2 mm in Y verfahren; gedrückt halten für fortlaufendes Verfahren</translation>
        </message>
        <message>
            <source>Go to…</source>
            <translation>Anfahren…</translation>
        </message>
        <message>
            <source>Click the canvas to choose where the pen goes; the path is shown before you confirm.</source>
            <translation>Klicken Sie auf die Zeichenfläche, um das Ziel des Stifts zu wählen; der Weg wird vor der Bestätigung angezeigt.</translation>
        </message>
        <message>
            <source>Turn motor %1 clockwise by one step</source>
            <translation>Motor %1 um einen Schritt im Uhrzeigersinn drehen</translation>
        </message>
        <message>
            <source>Turn motor %1 counter-clockwise by one step</source>
            <translation>Motor %1 um einen Schritt gegen den Uhrzeigersinn drehen</translation>
        </message>
        <message>
            <source>Step</source>
            <translation>Schritt</translation>
        </message>
        <message>
            <source>mm / °</source>
            <translation>mm / °</translation>
        </message>
        <message>
            <source> mm/s</source>
            <translation> mm/s</translation>
        </message>
        <message>
            <source>Pen up</source>
            <translation>Stift hoch</translation>
        </message>
        <message>
            <source>Lift the pen (Page Up on the canvas)</source>
            <translation>Stift anheben (Bild auf auf der Zeichenfläche)</translation>
        </message>
        <message>
            <source>Pen down</source>
            <translation>Stift ab</translation>
        </message>
        <message>
            <source>Lower the pen (Page Down on the canvas)</source>
            <translation>Stift absenken (Bild ab auf der Zeichenfläche)</translation>
        </message>
        <message>
            <source>Go</source>
            <translation>Los</translation>
        </message>
        <message>
            <source>Cancel</source>
            <translation>Abbrechen</translation>
        </message>
        <message>
            <source>Click the canvas where the pen should go.</source>
            <translation>Klicken Sie auf die Stelle der Zeichenfläche, die der Stift anfahren soll.</translation>
        </message>
        <message>
            <source>Home ($H)</source>
            <translation>Referenzfahrt ($H)</translation>
        </message>
        <message>
            <source>Set reference pose</source>
            <translation>Referenzpose setzen</translation>
        </message>
        <message>
            <source>Run the homing cycle</source>
            <translation>Referenzfahrt ausführen</translation>
        </message>
        <message>
            <source>Declare that the machine now stands at the profile's home pose</source>
            <translation>Festlegen, dass die Maschine jetzt in der Ausgangspose des Profils steht</translation>
        </message>
        <message>
            <source>Speed of XY jogs</source>
            <translation>Geschwindigkeit beim XY-Verfahren</translation>
        </message>
        <message>
            <source>Go to home pose</source>
            <translation>Zur Grundstellung fahren</translation>
        </message>
        <message>
            <source>Move the pen up to the profile's home pose by a checked move (the reference must be set)</source>
            <translation>Mit angehobenem Stift in einer geprüften Bewegung zur Grundstellung des Profils fahren (die Referenz muss gesetzt sein)</translation>
        </message>
        <message>
            <source>Speed</source>
            <translation>Geschwindigkeit</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::LayersPanel</name>
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
                <numerusform>%n Pfad</numerusform>
                <numerusform>%n Pfade</numerusform>
            </translation>
        </message>
        <message numerus="yes">
            <source>%n point(s)</source>
            <translation>
                <numerusform>%n Punkt</numerusform>
                <numerusform>%n Punkte</numerusform>
            </translation>
        </message>
        <message>
            <source>Fill of the selected layer</source>
            <translation>Füllung der gewählten Ebene</translation>
        </message>
        <message>
            <source>Outline</source>
            <translation>Umriss</translation>
        </message>
        <message>
            <source>Hatch</source>
            <translation>Schraffur</translation>
        </message>
        <message>
            <source>None</source>
            <translation>Keine</translation>
        </message>
        <message>
            <source>How the layer's filled shapes are drawn: their outline, parallel hatch lines inside them, or not at all (stroked shapes keep their stroke).</source>
            <translation>Wie die gefüllten Formen der Ebene gezeichnet werden: ihr Umriss, parallele Schraffurlinien darin oder gar nicht (Formen mit Kontur behalten ihre Kontur).</translation>
        </message>
        <message>
            <source> mm</source>
            <translation> mm</translation>
        </message>
        <message>
            <source> °</source>
            <translation> °</translation>
        </message>
        <message>
            <source>Crosshatch</source>
            <translation>Kreuzschraffur</translation>
        </message>
        <message>
            <source>Fill:</source>
            <translation>Füllung:</translation>
        </message>
        <message>
            <source>Hatch spacing:</source>
            <translation>Linienabstand:</translation>
        </message>
        <message>
            <source>Hatch angle:</source>
            <translation>Schraffurwinkel:</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::MachineBanner</name>
        <message>
            <source>Reset</source>
            <translation>Zurücksetzen</translation>
        </message>
        <message>
            <source>Soft reset (Ctrl-X): stops everything; the machine keeps its position unless it was moving.</source>
            <translation>Soft-Reset (Strg-X): hält alles an; die Maschine behält ihre Position, sofern sie sich nicht bewegt hat.</translation>
        </message>
        <message>
            <source>Unlock ($X)</source>
            <translation>Entsperren ($X)</translation>
        </message>
        <message>
            <source>Leave the alarm state without homing. Only when you know the machine stands where the studio shows it.</source>
            <translation>Den Alarmzustand ohne Referenzfahrt verlassen. Nur wenn Sie wissen, dass die Maschine dort steht, wo das Studio sie zeigt.</translation>
        </message>
        <message>
            <source>Dismiss</source>
            <translation>Schließen</translation>
        </message>
        <message>
            <source>Alarm %1: the machine stopped</source>
            <translation>Alarm %1: Die Maschine hat angehalten</translation>
        </message>
        <message>
            <source>Alarm: the machine is locked</source>
            <translation>Alarm: Die Maschine ist gesperrt</translation>
        </message>
        <message>
            <source>Error %1: a command was rejected</source>
            <translation>Fehler %1: Ein Befehl wurde abgelehnt</translation>
        </message>
        <message>
            <source>The board waits for a reset first: press Reset, then Unlock.</source>
            <translation>Die Steuerung erwartet zuerst ein Zurücksetzen: Drücken Sie Zurücksetzen, dann Entsperren.</translation>
        </message>
        <message>
            <source>Home ($H)</source>
            <translation>Referenzfahrt ($H)</translation>
        </message>
        <message>
            <source>Set reference pose</source>
            <translation>Referenzpose setzen</translation>
        </message>
        <message>
            <source>Run the homing cycle; the machine moves to its switches.</source>
            <translation>Referenzfahrt ausführen; die Maschine fährt an ihre Endschalter.</translation>
        </message>
        <message>
            <source>Declare that the machine now stands at the profile's home pose (G10 L20).</source>
            <translation>Festlegen, dass die Maschine jetzt in der Ausgangspose des Profils steht (G10 L20).</translation>
        </message>
        <message>
            <source>Position unknown: nothing moves until it is set</source>
            <translation>Position unbekannt: Nichts bewegt sich, bis sie gesetzt ist</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::MachineDialogs</name>
        <message>
            <source>Set the reference pose?

The studio will take the machine's current position to be the home pose of "%1": motor 1 at %2°, motor 2 at %3°. Every later move is computed from it.

Confirm only if the arms stand exactly in that pose now. If they stand elsewhere, moves will land in the wrong place and can drive the arms into each other or into the base.</source>
            <translation>Referenzstellung setzen?

Das Studio nimmt die aktuelle Position der Maschine als Grundstellung von „%1“: Motor 1 bei %2°, Motor 2 bei %3°. Jede spätere Bewegung wird daraus berechnet.

Bestätigen Sie nur, wenn die Arme jetzt genau in dieser Stellung stehen. Stehen sie anders, landen Bewegungen an der falschen Stelle und können die Arme ineinander oder in die Basis fahren.</translation>
        </message>
        <message>
            <source>Set reference pose</source>
            <translation>Referenzstellung setzen</translation>
        </message>
        <message>
            <source>The arms stand in the home pose: set it</source>
            <translation>Die Arme stehen in der Grundstellung: setzen</translation>
        </message>
        <message>
            <source>Cancel</source>
            <translation>Abbrechen</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::MachinePanel</name>
        <message>
            <source>Idle</source>
            <translation>Bereit</translation>
        </message>
        <message>
            <source>Running</source>
            <translation>Läuft</translation>
        </message>
        <message>
            <source>On hold</source>
            <translation>Angehalten</translation>
        </message>
        <message>
            <source>Jogging</source>
            <translation>Verfährt</translation>
        </message>
        <message>
            <source>Alarm</source>
            <translation>Alarm</translation>
        </message>
        <message>
            <source>Door open</source>
            <translation>Tür offen</translation>
        </message>
        <message>
            <source>Check mode</source>
            <translation>Prüfmodus</translation>
        </message>
        <message>
            <source>Homing</source>
            <translation>Referenzfahrt</translation>
        </message>
        <message>
            <source>Sleeping</source>
            <translation>Ruhezustand</translation>
        </message>
        <message>
            <source>Unknown</source>
            <translation>Unbekannt</translation>
        </message>
        <message>
            <source>Refresh</source>
            <translation>Aktualisieren</translation>
        </message>
        <message>
            <source>List the serial ports again</source>
            <translation>Serielle Schnittstellen neu auflisten</translation>
        </message>
        <message>
            <source>Connect</source>
            <translation>Verbinden</translation>
        </message>
        <message>
            <source>Disconnect</source>
            <translation>Trennen</translation>
        </message>
        <message>
            <source>Baud</source>
            <translation>Baud</translation>
        </message>
        <message>
            <source>Connection</source>
            <translation>Verbindung</translation>
        </message>
        <message>
            <source>Status</source>
            <translation>Status</translation>
        </message>
        <message>
            <source>State</source>
            <translation>Zustand</translation>
        </message>
        <message>
            <source>Pen (X, Y)</source>
            <translation>Stift (X, Y)</translation>
        </message>
        <message>
            <source>Motors (θ1, θ2)</source>
            <translation>Motoren (θ1, θ2)</translation>
        </message>
        <message>
            <source>Buffers</source>
            <translation>Puffer</translation>
        </message>
        <message>
            <source>Simulated machine (built in)</source>
            <translation>Simulierte Maschine (eingebaut)</translation>
        </message>
        <message>
            <source>Cannot connect</source>
            <translation>Verbindung nicht möglich</translation>
        </message>
        <message>
            <source>Connected to %1</source>
            <translation>Verbunden mit %1</translation>
        </message>
        <message>
            <source>Not connected</source>
            <translation>Nicht verbunden</translation>
        </message>
        <message>
            <source>Offline</source>
            <translation>Offline</translation>
        </message>
        <message>
            <source>%1, %2 mm</source>
            <translation>%1, %2 mm</translation>
        </message>
        <message>
            <source>%1°, %2°</source>
            <translation>%1°, %2°</translation>
        </message>
        <message>
            <source>planner %1 of %2 blocks free, RX %3 of %4 bytes free</source>
            <translation>Planer %1 von %2 Blöcken frei, RX %3 von %4 Bytes frei</translation>
        </message>
        <message>
            <source>Pen</source>
            <translation>Stift</translation>
        </message>
        <message>
            <source>Review and write...</source>
            <translation>Prüfen und schreiben...</translation>
        </message>
        <message>
            <source>Compare the board's settings with the profile and write the differences (a backup is saved first)</source>
            <translation>Die Einstellungen der Steuerung mit dem Profil vergleichen und die Unterschiede schreiben (vorher wird eine Sicherung gespeichert)</translation>
        </message>
        <message>
            <source>No answer from the machine</source>
            <translation>Keine Antwort von der Maschine</translation>
        </message>
        <message>
            <source>Connecting to %1: waiting for the board to answer...</source>
            <translation>Verbinde mit %1: warte auf die Antwort der Steuerung...</translation>
        </message>
        <message>
            <source>up</source>
            <translation>oben</translation>
        </message>
        <message>
            <source>down (drawing)</source>
            <translation>unten (zeichnet)</translation>
        </message>
        <message>
            <source>not known yet</source>
            <translation>noch unbekannt</translation>
        </message>
        <message>
            <source>unknown (set the reference pose)</source>
            <translation>unbekannt (Referenzpose setzen)</translation>
        </message>
        <message>
            <source>Cannot open %1.</source>
            <translation>%1 lässt sich nicht öffnen.</translation>
        </message>
    </context>
    <context>
        <name>fivebar::session::MachineSession</name>
        <message>
            <source>No job is planned: open a drawing and let it plan first.</source>
            <translation>Kein Auftrag geplant: Öffnen Sie zuerst eine Zeichnung und lassen Sie sie planen.</translation>
        </message>
        <message>
            <source>No checked frame of the job: %1</source>
            <translation>Kein geprüfter Umriss des Auftrags: %1</translation>
        </message>
        <message>
            <source>The frame was not sent (see the console).</source>
            <translation>Der Umriss wurde nicht gesendet (siehe Konsole).</translation>
        </message>
        <message>
            <source>Frame: the job's outline, %1 mm, pen up</source>
            <translation>Umriss: der Umriss des Auftrags, %1 mm, Stift oben</translation>
        </message>
        <message>
            <source>Cannot open %1.</source>
            <translation>%1 kann nicht geöffnet werden.</translation>
        </message>
        <message>
            <source>Connected to %1.</source>
            <translation>Verbunden mit %1.</translation>
        </message>
        <message>
            <source>Disconnected.</source>
            <translation>Getrennt.</translation>
        </message>
        <message>
            <source>Not connected: %1 was not sent.</source>
            <translation>Nicht verbunden: %1 wurde nicht gesendet.</translation>
        </message>
        <message>
            <source>Not sent (%1): %2</source>
            <translation>Nicht gesendet (%1): %2</translation>
        </message>
        <message>
            <source>A job is running: %1 was not sent.</source>
            <translation>Ein Auftrag läuft: %1 wurde nicht gesendet.</translation>
        </message>
        <message>
            <source>Jog refused: the machine is not idle, not connected or a job is running.</source>
            <translation>Verfahren abgelehnt: Die Maschine ist nicht bereit, nicht verbunden, oder ein Auftrag läuft.</translation>
        </message>
        <message>
            <source>[soft reset]</source>
            <translation>[Soft-Reset]</translation>
        </message>
        <message>
            <source>[feed hold]</source>
            <translation>[Vorschub halten]</translation>
        </message>
        <message>
            <source>[cycle start]</source>
            <translation>[Zyklusstart]</translation>
        </message>
        <message>
            <source>%1 was rejected: %2</source>
            <translation>%1 wurde abgelehnt: %2</translation>
        </message>
        <message>
            <source>The machine is locked (alarm state). Unlock it with $X or home it with $H once you know where it stands.</source>
            <translation>Die Maschine ist gesperrt (Alarmzustand). Entsperren Sie sie mit $X oder führen Sie mit $H eine Referenzfahrt aus, sobald Sie wissen, wo sie steht.</translation>
        </message>
        <message>
            <source>The board reset (Grbl %1).</source>
            <translation>Die Steuerung wurde zurückgesetzt (Grbl %1).</translation>
        </message>
        <message>
            <source>Connection lost: %1</source>
            <translation>Verbindung verloren: %1</translation>
        </message>
        <message>
            <source>the simulated machine</source>
            <translation>der simulierten Maschine</translation>
        </message>
        <message>
            <source>set the reference pose (Machine panel) or home the machine</source>
            <translation>setzen Sie die Referenzstellung (Maschinen-Panel) oder referenzieren Sie die Maschine</translation>
        </message>
        <message>
            <source>%1 at %2 baud</source>
            <translation>%1 mit %2 Baud</translation>
        </message>
        <message>
            <source>Opened %1; waiting for the board to answer...</source>
            <translation>%1 geöffnet; warte auf die Antwort der Steuerung...</translation>
        </message>
        <message>
            <source>No GRBL board answered on %1 within %2 s. Check that the port is the machine's, that the baud rate matches its firmware (GRBL 1.1: usually 115200) and that it is powered.</source>
            <translation>Auf %1 hat innerhalb von %2 s keine GRBL-Steuerung geantwortet. Prüfen Sie, ob der Anschluss der der Maschine ist, ob die Baudrate zu ihrer Firmware passt (GRBL 1.1: meist 115200) und ob sie eingeschaltet ist.</translation>
        </message>
        <message>
            <source>Not sent: %1</source>
            <translation>Nicht gesendet: %1</translation>
        </message>
        <message>
            <source>Unchecked: %1</source>
            <translation>Ungeprüft: %1</translation>
        </message>
        <message>
            <source>The machine's position is not known yet (no status report with its work position): wait a moment, or set the reference pose.</source>
            <translation>Die Position der Maschine ist noch unbekannt (kein Statusbericht mit ihrer Werkstückposition): Warten Sie einen Moment oder setzen Sie die Referenzstellung.</translation>
        </message>
        <message>
            <source>The machine is still moving or busy: send a move when it stands still (Idle), so it can be checked from where the machine really is.</source>
            <translation>Die Maschine bewegt sich noch oder ist beschäftigt: Senden Sie eine Bewegung, wenn sie stillsteht (Bereit), damit sie von der wirklichen Position aus geprüft werden kann.</translation>
        </message>
        <message>
            <source>Console lines are sent UNCHECKED from now on.</source>
            <translation>Konsolenzeilen werden ab jetzt UNGEPRÜFT gesendet.</translation>
        </message>
        <message>
            <source>Console lines are checked again.</source>
            <translation>Konsolenzeilen werden wieder geprüft.</translation>
        </message>
        <message>
            <source>The machine must be connected, idle and its position known.</source>
            <translation>Die Maschine muss verbunden und bereit sein, und ihre Position muss bekannt sein.</translation>
        </message>
        <message>
            <source>The profile's home pose does not close the linkage.</source>
            <translation>Die Grundstellung des Profils schließt das Gestänge nicht.</translation>
        </message>
        <message>
            <source>No checked move to the home pose: %1</source>
            <translation>Keine geprüfte Bewegung zur Grundstellung: %1</translation>
        </message>
        <message>
            <source>The move was not sent (see the console).</source>
            <translation>Die Bewegung wurde nicht gesendet (siehe Konsole).</translation>
        </message>
        <message>
            <source>choose a target inside the workspace</source>
            <translation>wählen Sie ein Ziel innerhalb des Arbeitsbereichs</translation>
        </message>
        <message>
            <source>Move not sent: %1</source>
            <translation>Bewegung nicht gesendet: %1</translation>
        </message>
        <message>
            <source>Home the machine (Home), or put the arms in the home pose and press Set reference pose.</source>
            <translation>Referenzfahrt ausführen (Home) oder die Arme in die Grundstellung bringen und Referenzpose setzen drücken.</translation>
        </message>
        <message>
            <source>Put the arms in the home pose by hand and press Set reference pose.</source>
            <translation>Die Arme von Hand in die Grundstellung bringen und Referenzpose setzen drücken.</translation>
        </message>
        <message>
            <source>Reading where the machine stands...</source>
            <translation>Lese, wo die Maschine steht …</translation>
        </message>
        <message>
            <source>The machine's position is not known: this board has not been referenced from this computer yet. %1</source>
            <translation>Die Position der Maschine ist nicht bekannt: Diese Platine wurde von diesem Computer aus noch nicht referenziert. %1</translation>
        </message>
        <message>
            <source>The machine's position is not known: the board was powered up or reset since it was last seen, so the position it reports says nothing about where the arms stand. %1</source>
            <translation>Die Position der Maschine ist nicht bekannt: Die Platine wurde seit dem letzten Kontakt eingeschaltet oder zurückgesetzt, die gemeldete Position sagt also nichts darüber, wo die Arme stehen. %1</translation>
        </message>
        <message>
            <source>The machine's position is not known: it was reset or stopped hard while moving, and the motors may have lost steps. %1</source>
            <translation>Die Position der Maschine ist nicht bekannt: Sie wurde während der Bewegung zurückgesetzt oder hart gestoppt, die Motoren haben eventuell Schritte verloren. %1</translation>
        </message>
        <message>
            <source>The machine's position is not known: the homing cycle moved the arms and did not finish. %1</source>
            <translation>Die Position der Maschine ist nicht bekannt: Die Referenzfahrt hat die Arme bewegt und wurde nicht beendet. %1</translation>
        </message>
        <message>
            <source>The machine's position is not known: it moved while no program watched it (a job cut off by a crash, a closed connection or another program). %1</source>
            <translation>Die Position der Maschine ist nicht bekannt: Sie hat sich bewegt, während kein Programm zusah (ein durch Absturz, geschlossene Verbindung oder ein anderes Programm abgebrochener Auftrag). %1</translation>
        </message>
        <message>
            <source>Not connected.</source>
            <translation>Nicht verbunden.</translation>
        </message>
        <message>
            <source>Moves are sent although the board's settings differ from the profile (expert override).</source>
            <translation>Bewegungen werden gesendet, obwohl die Einstellungen der Platine vom Profil abweichen (Expertenmodus).</translation>
        </message>
        <message>
            <source>The machine is not connected.</source>
            <translation>Die Maschine ist nicht verbunden.</translation>
        </message>
        <message>
            <source>A job is running.</source>
            <translation>Ein Auftrag läuft.</translation>
        </message>
        <message>
            <source>The board's settings %1 differ from the profile, so the machine would not move as planned: write the profile's settings (Machine settings...) first.</source>
            <translation>Die Einstellungen %1 der Platine weichen vom Profil ab, die Maschine würde sich also nicht wie geplant bewegen: zuerst die Einstellungen des Profils schreiben (Maschineneinstellungen …).</translation>
        </message>
        <message>
            <source>The machine is not idle.</source>
            <translation>Die Maschine ist nicht im Leerlauf.</translation>
        </message>
        <message>
            <source>Jog refused: %1</source>
            <translation>Verfahren abgelehnt: %1</translation>
        </message>
        <message>
            <source>[feed override 100 %]</source>
            <translation>[Vorschub-Override 100 %]</translation>
        </message>
        <message>
            <source>[feed override +10 %]</source>
            <translation>[Vorschub-Override +10 %]</translation>
        </message>
        <message>
            <source>[feed override -10 %]</source>
            <translation>[Vorschub-Override -10 %]</translation>
        </message>
        <message>
            <source>[feed override +1 %]</source>
            <translation>[Vorschub-Override +1 %]</translation>
        </message>
        <message>
            <source>[feed override -1 %]</source>
            <translation>[Vorschub-Override -1 %]</translation>
        </message>
        <message>
            <source>[rapid override 100 %]</source>
            <translation>[Eilgang-Override 100 %]</translation>
        </message>
        <message>
            <source>[rapid override 50 %]</source>
            <translation>[Eilgang-Override 50 %]</translation>
        </message>
        <message>
            <source>[rapid override 25 %]</source>
            <translation>[Eilgang-Override 25 %]</translation>
        </message>
        <message numerus="yes">
            <source>%1 (jog in %n checked move(s))</source>
            <translation>
                <numerusform>%1 (Verfahren in %n geprüften Bewegung)</numerusform>
                <numerusform>%1 (Verfahren in %n geprüften Bewegungen)</numerusform>
            </translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::MachineSettingsDialog</name>
        <message>
            <source>Machine settings</source>
            <translation>Maschineneinstellungen</translation>
        </message>
        <message>
            <source>The board's GRBL settings next to the values the machine profile needs. Writing saves a backup of the board's settings first.</source>
            <translation>Die GRBL-Einstellungen der Steuerung neben den Werten, die das Maschinenprofil braucht. Vor dem Schreiben wird eine Sicherung der Einstellungen der Steuerung gespeichert.</translation>
        </message>
        <message>
            <source>Setting</source>
            <translation>Einstellung</translation>
        </message>
        <message>
            <source>Board</source>
            <translation>Steuerung</translation>
        </message>
        <message>
            <source>Profile</source>
            <translation>Profil</translation>
        </message>
        <message>
            <source>Differs</source>
            <translation>Abweichend</translation>
        </message>
        <message>
            <source>Read from board</source>
            <translation>Von der Steuerung lesen</translation>
        </message>
        <message>
            <source>Write differences...</source>
            <translation>Abweichungen schreiben...</translation>
        </message>
        <message>
            <source>Close</source>
            <translation>Schließen</translation>
        </message>
        <message>
            <source>The machine was disconnected.</source>
            <translation>Die Verbindung zur Maschine wurde getrennt.</translation>
        </message>
        <message>
            <source>Connect the machine first.</source>
            <translation>Zuerst die Maschine verbinden.</translation>
        </message>
        <message>
            <source>A job is running.</source>
            <translation>Ein Auftrag läuft.</translation>
        </message>
        <message>
            <source>Still talking to the board.</source>
            <translation>Die Kommunikation mit der Steuerung läuft noch.</translation>
        </message>
        <message>
            <source>The machine must be idle (or in alarm) to change settings.</source>
            <translation>Zum Ändern der Einstellungen muss die Maschine im Ruhezustand (oder im Alarm) sein.</translation>
        </message>
        <message>
            <source>Reading the board's settings...</source>
            <translation>Einstellungen der Steuerung werden gelesen...</translation>
        </message>
        <message>
            <source>Nothing to write: read the board's settings first.</source>
            <translation>Nichts zu schreiben: zuerst die Einstellungen der Steuerung lesen.</translation>
        </message>
        <message>
            <source>Write settings</source>
            <translation>Einstellungen schreiben</translation>
        </message>
        <message numerus="yes">
            <source>Write %n setting(s) to the board? Its current settings are saved to a backup file first.</source>
            <translation>
                <numerusform>%n Einstellung auf die Steuerung schreiben? Ihre aktuellen Einstellungen werden zuvor in einer Sicherungsdatei gespeichert.</numerusform>
                <numerusform>%n Einstellungen auf die Steuerung schreiben? Ihre aktuellen Einstellungen werden zuvor in einer Sicherungsdatei gespeichert.</numerusform>
            </translation>
        </message>
        <message>
            <source>The board's settings match the profile.</source>
            <translation>Die Einstellungen der Steuerung stimmen mit dem Profil überein.</translation>
        </message>
        <message numerus="yes">
            <source>%n setting(s) differ from the profile.</source>
            <translation>
                <numerusform>%n Einstellung weicht vom Profil ab.</numerusform>
                <numerusform>%n Einstellungen weichen vom Profil ab.</numerusform>
            </translation>
        </message>
        <message numerus="yes">
            <source>%n setting(s) written. Backup of the previous settings: %1</source>
            <translation>
                <numerusform>%n Einstellung geschrieben. Sicherung der vorherigen Einstellungen: %1</numerusform>
                <numerusform>%n Einstellungen geschrieben. Sicherung der vorherigen Einstellungen: %1</numerusform>
            </translation>
        </message>
        <message>
            <source>Writing settings one at a time... Backup: %1</source>
            <translation>Einstellungen werden einzeln geschrieben... Sicherung: %1</translation>
        </message>
        <message>
            <source>Failed: %1</source>
            <translation>Fehlgeschlagen: %1</translation>
        </message>
        <message>
            <source>yes</source>
            <translation>ja</translation>
        </message>
        <message>
            <source>Meaning</source>
            <translation>Bedeutung</translation>
        </message>
        <message>
            <source>Unit</source>
            <translation>Einheit</translation>
        </message>
        <message>
            <source>(not a GRBL 1.1h setting)</source>
            <translation>(keine Einstellung von GRBL 1.1h)</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::MachinePanels</name>
        <message>
            <source>Machine</source>
            <translation>Maschine</translation>
        </message>
        <message>
            <source>Run</source>
            <translation>Ausführen</translation>
        </message>
        <message>
            <source>Jog</source>
            <translation>Verfahren</translation>
        </message>
        <message>
            <source>Console</source>
            <translation>Konsole</translation>
        </message>
        <message>
            <source>Machine profile</source>
            <translation>Profil</translation>
        </message>
        <message>
            <source>Machine &amp;settings...</source>
            <translation>Maschinen&amp;einstellungen...</translation>
        </message>
        <message>
            <source>A job is running</source>
            <translation>Ein Auftrag läuft</translation>
        </message>
        <message>
            <source>The machine is drawing "%1". Quitting the studio would leave it without its stream of lines.

Hold, stop and quit: the machine stops cleanly and the progress is saved, so you can resume later.</source>
            <translation>Die Maschine zeichnet „%1“. Beim Beenden des Studios bekäme sie keine weiteren Zeilen.

Anhalten, stoppen und beenden: Die Maschine hält sauber an und der Fortschritt wird gespeichert, sodass Sie später fortsetzen können.</translation>
        </message>
        <message>
            <source>Hold, stop and quit</source>
            <translation>Anhalten, stoppen und beenden</translation>
        </message>
        <message>
            <source>Keep running</source>
            <translation>Weiterlaufen lassen</translation>
        </message>
        <message>
            <source>The job has ended</source>
            <translation>Der Auftrag ist beendet</translation>
        </message>
        <message>
            <source>The job "%1" has ended. Quit FiveBar Studio?</source>
            <translation>Der Auftrag „%1“ ist beendet. FiveBar Studio beenden?</translation>
        </message>
        <message>
            <source>Quit</source>
            <translation>Beenden</translation>
        </message>
        <message>
            <source>Cancel</source>
            <translation>Abbrechen</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::ModePanel</name>
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
            <source>Workspace legend</source>
            <translation>Arbeitsraum-Legende</translation>
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
        <name>fivebar::widgets::ParetoPlot</name>
        <message>
            <source>Footprint (cm²)</source>
            <translation>Platzbedarf (cm²)</translation>
        </message>
        <message>
            <source>Worst condition number</source>
            <translation>Schlechteste Konditionszahl</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::PlacementPanel</name>
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
            <source>Keep aspect ratio</source>
            <translation>Seitenverhältnis beibehalten</translation>
        </message>
        <message>
            <source>Width:</source>
            <translation>Breite:</translation>
        </message>
        <message>
            <source>Height:</source>
            <translation>Höhe:</translation>
        </message>
        <message>
            <source>Actual size</source>
            <translation>Originalgröße</translation>
        </message>
        <message>
            <source>Draw the drawing at its true size (100 %)</source>
            <translation>Die Zeichnung in ihrer wahren Größe zeichnen (100 %)</translation>
        </message>
        <message>
            <source>Scale the drawing to fill the largest singularity-free rectangle</source>
            <translation>Die Zeichnung so skalieren, dass sie das größte singularitätsfreie Rechteck füllt</translation>
        </message>
        <message>
            <source>No singularity-free area to fit the drawing into.</source>
            <translation>Kein singularitätsfreier Bereich, in den die Zeichnung passt.</translation>
        </message>
        <message>
            <source>Fitted: %1 %</source>
            <translation>Eingepasst: %1 %</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::PreviewPanel</name>
        <message>
            <source>%1 % of what this machine can do</source>
            <translation>%1 % des Möglichen</translation>
        </message>
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
            <translation>Nach Geschwindigkeit färben</translation>
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
            <source>Working mode: &lt;b&gt;%1&lt;/b&gt;</source>
            <translation>Arbeitsmodus: &lt;b&gt;%1&lt;/b&gt;</translation>
        </message>
        <message>
            <source>No problems: every move is reachable and safe.</source>
            <translation>Keine Probleme: Jede Bewegung ist erreichbar und sicher.</translation>
        </message>
        <message>
            <source>What to do: %1</source>
            <translation>Was zu tun ist: %1</translation>
        </message>
        <message>
            <source>&lt;table&gt;&lt;tr&gt;&lt;td&gt;Working mode:&lt;/td&gt;&lt;td&gt;&lt;b&gt;%1&lt;/b&gt;&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;Estimated time:&lt;/td&gt;&lt;td&gt;&lt;b&gt;%2&lt;/b&gt;&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;/td&gt;&lt;td&gt;%8&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;Pen down:&lt;/td&gt;&lt;td&gt;%3 mm&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;Pen up:&lt;/td&gt;&lt;td&gt;%4 mm&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;Segments:&lt;/td&gt;&lt;td&gt;%5&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;Max deviation:&lt;/td&gt;&lt;td&gt;%6 mm&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;Singularity margin:&lt;/td&gt;&lt;td&gt;%7 deg&lt;/td&gt;&lt;/tr&gt;&lt;/table&gt;</source>
            <translation>&lt;table&gt;&lt;tr&gt;&lt;td&gt;Arbeitsmodus:&lt;/td&gt;&lt;td&gt;&lt;b&gt;%1&lt;/b&gt;&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;Geschätzte Zeit:&lt;/td&gt;&lt;td&gt;&lt;b&gt;%2&lt;/b&gt;&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;/td&gt;&lt;td&gt;%8&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;Stift unten:&lt;/td&gt;&lt;td&gt;%3 mm&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;Stift oben:&lt;/td&gt;&lt;td&gt;%4 mm&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;Segmente:&lt;/td&gt;&lt;td&gt;%5&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;Größte Abweichung:&lt;/td&gt;&lt;td&gt;%6 mm&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;Singularitätsabstand:&lt;/td&gt;&lt;td&gt;%7 Grad&lt;/td&gt;&lt;/tr&gt;&lt;/table&gt;</translation>
        </message>
        <message>
            <source>; </source>
            <translation>; </translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::ProfileEditor</name>
        <message>
            <source>Load preset</source>
            <translation>Vorlage laden</translation>
        </message>
        <message>
            <source>Import…</source>
            <translation>Importieren…</translation>
        </message>
        <message>
            <source>Load a machine profile from a JSON file</source>
            <translation>Ein Maschinenprofil aus einer JSON-Datei laden</translation>
        </message>
        <message>
            <source>Export…</source>
            <translation>Exportieren…</translation>
        </message>
        <message>
            <source>Save this machine profile as a JSON file</source>
            <translation>Dieses Maschinenprofil als JSON-Datei speichern</translation>
        </message>
        <message>
            <source>Machine</source>
            <translation>Maschine</translation>
        </message>
        <message>
            <source>Name</source>
            <translation>Name</translation>
        </message>
        <message>
            <source>Geometry</source>
            <translation>Geometrie</translation>
        </message>
        <message>
            <source>Joint limits</source>
            <translation>Gelenkgrenzen</translation>
        </message>
        <message>
            <source>Motors</source>
            <translation>Motoren</translation>
        </message>
        <message>
            <source>Tool</source>
            <translation>Werkzeug</translation>
        </message>
        <message>
            <source>Motion and safety</source>
            <translation>Bewegung und Sicherheit</translation>
        </message>
        <message>
            <source>Connection and home pose</source>
            <translation>Verbindung und Ausgangspose</translation>
        </message>
        <message>
            <source> mm</source>
            <translation> mm</translation>
        </message>
        <message>
            <source> °</source>
            <translation> °</translation>
        </message>
        <message>
            <source> s</source>
            <translation> s</translation>
        </message>
        <message>
            <source>Limit the motor angles</source>
            <translation>Motorwinkel begrenzen</translation>
        </message>
        <message>
            <source> °/min</source>
            <translation> °/min</translation>
        </message>
        <message>
            <source> °/s²</source>
            <translation> °/s²</translation>
        </message>
        <message>
            <source>Pen servo (M3 S / M5)</source>
            <translation>Stiftservo (M3 S/M5)</translation>
        </message>
        <message>
            <source>Z axis</source>
            <translation>Z-Achse</translation>
        </message>
        <message>
            <source>Laser (M4 S / M5)</source>
            <translation>Laser (M4 S / M5)</translation>
        </message>
        <message>
            <source> mm/min</source>
            <translation> mm/min</translation>
        </message>
        <message>
            <source>Working mode (built)</source>
            <translation>Arbeitsmodus (Aufbau)</translation>
        </message>
        <message>
            <source>Assembly mode</source>
            <translation>Montagemodus</translation>
        </message>
        <message>
            <source> mm/s</source>
            <translation> mm/s</translation>
        </message>
        <message>
            <source>The machine has homing switches ($H)</source>
            <translation>Die Maschine hat Referenzschalter ($H)</translation>
        </message>
        <message>
            <source>The profile is not applied until these problems are fixed.</source>
            <translation>Das Profil wird erst übernommen, wenn diese Probleme behoben sind.</translation>
        </message>
        <message>
            <source>%1 cannot be used:
%2</source>
            <translation>%1 kann nicht verwendet werden:
%2</translation>
        </message>
        <message>
            <source>Fix the profile's problems before exporting it.</source>
            <translation>Beheben Sie die Probleme des Profils, bevor Sie es exportieren.</translation>
        </message>
        <message>
            <source>Import machine profile</source>
            <translation>Maschinenprofil importieren</translation>
        </message>
        <message>
            <source>Machine profiles (*.json)</source>
            <translation>Maschinenprofile (*.json)</translation>
        </message>
        <message>
            <source>Import failed</source>
            <translation>Import fehlgeschlagen</translation>
        </message>
        <message>
            <source>Export machine profile</source>
            <translation>Maschinenprofil exportieren</translation>
        </message>
        <message>
            <source>Export failed</source>
            <translation>Export fehlgeschlagen</translation>
        </message>
        <message>
            <source> steps/°</source>
            <translation> Schritte/°</translation>
        </message>
        <message>
            <source> baud</source>
            <translation> Baud</translation>
        </message>
    </context>
    <context>
        <name>ProfileField</name>
        <message>
            <source>Driving link a1</source>
            <translation>Antriebsglied a1</translation>
        </message>
        <message>
            <source>Floating link b1</source>
            <translation>Koppelglied b1</translation>
        </message>
        <message>
            <source>Driving link a2</source>
            <translation>Antriebsglied a2</translation>
        </message>
        <message>
            <source>Floating link b2</source>
            <translation>Koppelglied b2</translation>
        </message>
        <message>
            <source>Motor distance w</source>
            <translation>Motorabstand w</translation>
        </message>
        <message>
            <source>θ1 minimum</source>
            <translation>θ1 Minimum</translation>
        </message>
        <message>
            <source>θ1 maximum</source>
            <translation>θ1 Maximum</translation>
        </message>
        <message>
            <source>θ2 minimum</source>
            <translation>θ2 Minimum</translation>
        </message>
        <message>
            <source>θ2 maximum</source>
            <translation>θ2 Maximum</translation>
        </message>
        <message>
            <source>Motor 1 steps per degree</source>
            <translation>Motor 1 Schritte pro Grad</translation>
        </message>
        <message>
            <source>Motor 2 steps per degree</source>
            <translation>Motor 2 Schritte pro Grad</translation>
        </message>
        <message>
            <source>Motor 1 maximum speed</source>
            <translation>Motor 1 Höchstgeschwindigkeit</translation>
        </message>
        <message>
            <source>Motor 2 maximum speed</source>
            <translation>Motor 2 Höchstgeschwindigkeit</translation>
        </message>
        <message>
            <source>Motor 1 acceleration</source>
            <translation>Motor 1 Beschleunigung</translation>
        </message>
        <message>
            <source>Motor 2 acceleration</source>
            <translation>Motor 2 Beschleunigung</translation>
        </message>
        <message>
            <source>Junction deviation</source>
            <translation>Eckenabweichung</translation>
        </message>
        <message>
            <source>Pen up S value</source>
            <translation>S-Wert Stift hoch</translation>
        </message>
        <message>
            <source>Pen down S value</source>
            <translation>S-Wert Stift ab</translation>
        </message>
        <message>
            <source>Pen up delay</source>
            <translation>Wartezeit Stift hoch</translation>
        </message>
        <message>
            <source>Pen down delay</source>
            <translation>Wartezeit Stift ab</translation>
        </message>
        <message>
            <source>Z up</source>
            <translation>Z oben</translation>
        </message>
        <message>
            <source>Z down</source>
            <translation>Z unten</translation>
        </message>
        <message>
            <source>Z feed</source>
            <translation>Z-Vorschub</translation>
        </message>
        <message>
            <source>Laser power S value</source>
            <translation>S-Wert Laserleistung</translation>
        </message>
        <message>
            <source>Drawing speed</source>
            <translation>Zeichengeschwindigkeit</translation>
        </message>
        <message>
            <source>Travel speed</source>
            <translation>Verfahrgeschwindigkeit</translation>
        </message>
        <message>
            <source>Type II singularity margin</source>
            <translation>Abstand zur Typ-II-Singularität</translation>
        </message>
        <message>
            <source>Type I singularity margin</source>
            <translation>Abstand zur Typ-I-Singularität</translation>
        </message>
        <message>
            <source>Baud rate</source>
            <translation>Baudrate</translation>
        </message>
        <message>
            <source>Home θ1</source>
            <translation>Ausgangspose θ1</translation>
        </message>
        <message>
            <source>Home θ2</source>
            <translation>Ausgangspose θ2</translation>
        </message>
        <message>
            <source>Calibration format version</source>
            <translation>Version des Kalibrierformats</translation>
        </message>
        <message>
            <source>Held-out marks</source>
            <translation>Zurückgehaltene Marken</translation>
        </message>
        <message>
            <source>Largest residual of the fit</source>
            <translation>Größtes Residuum der Anpassung</translation>
        </message>
        <message>
            <source>Marks used by the fit</source>
            <translation>Von der Anpassung genutzte Marken</translation>
        </message>
        <message>
            <source>Motor 1 backlash</source>
            <translation>Spiel Motor 1</translation>
        </message>
        <message>
            <source>Motor 1 zero offset</source>
            <translation>Nullpunktversatz Motor 1</translation>
        </message>
        <message>
            <source>Motor 2 backlash</source>
            <translation>Spiel Motor 2</translation>
        </message>
        <message>
            <source>Motor 2 zero offset</source>
            <translation>Nullpunktversatz Motor 2</translation>
        </message>
        <message>
            <source>Pen offset across b1</source>
            <translation>Stiftversatz quer zu b1</translation>
        </message>
        <message>
            <source>Pen offset along b1</source>
            <translation>Stiftversatz entlang b1</translation>
        </message>
        <message>
            <source>RMS error on held-out marks</source>
            <translation>RMS-Fehler der zurückgehaltenen Marken</translation>
        </message>
        <message>
            <source>RMS residual of the fit</source>
            <translation>RMS-Residuum der Anpassung</translation>
        </message>
    </context>
    <context>
        <name>fivebar::session::RunController</name>
        <message>
            <source>Not started: the board's soft limits would stop this job with an alarm (ALARM:2): %1. The board checks its travel ($130, $131) in machine coordinates, which the reference pose shifted against the drawing's. Home the machine, or make the board's settings match the profile (Machine settings...), then start again.</source>
            <translation>Nicht gestartet: Die Software-Endlagen der Steuerung würden diesen Auftrag mit einem Alarm (ALARM:2) anhalten: %1. Die Steuerung prüft ihren Verfahrweg ($130, $131) in Maschinenkoordinaten, und die Referenzpose hat diese gegenüber denen der Zeichnung verschoben. Die Maschine referenzieren (Referenzfahrt) oder die Einstellungen der Steuerung an das Profil angleichen (Maschineneinstellungen...), dann erneut starten.</translation>
        </message>
        <message>
            <source>The connection was closed during the run. The progress is saved beside the job: reconnect and resume.</source>
            <translation>Die Verbindung wurde während des Auftrags getrennt. Der Fortschritt ist neben dem Auftrag gespeichert: Verbinden Sie erneut und setzen Sie fort.</translation>
        </message>
        <message>
            <source>Cannot start: connect the machine, wait until it is idle, and let the job plan first.</source>
            <translation>Start nicht möglich: Verbinden Sie die Maschine, warten Sie, bis sie bereit ist, und lassen Sie den Auftrag zuerst planen.</translation>
        </message>
        <message>
            <source>Cannot create the job folder %1.</source>
            <translation>Der Auftragsordner %1 kann nicht angelegt werden.</translation>
        </message>
        <message>
            <source>Nothing to resume: there is no saved progress beside %1.</source>
            <translation>Nichts fortzusetzen: Neben %1 ist kein Fortschritt gespeichert.</translation>
        </message>
        <message>
            <source>line %1 of %2</source>
            <translation>Zeile %1 von %2</translation>
        </message>
        <message>
            <source>The run of "%1" was interrupted at %2: %3</source>
            <translation>Der Lauf von „%1“ wurde bei %2 unterbrochen: %3</translation>
        </message>
        <message>
            <source>press Resume</source>
            <translation>drücken Sie Fortsetzen</translation>
        </message>
        <message>
            <source>Resume</source>
            <translation>Fortsetzen</translation>
        </message>
        <message>
            <source>The machine raised an alarm and the job stopped (the banner in the Machine panel says why). The progress is saved: clear the alarm (Reset, Unlock), check the pen stands where the studio shows it, then press Resume.</source>
            <translation>Die Maschine hat einen Alarm ausgelöst und der Auftrag wurde angehalten (das Banner im Maschinen-Panel sagt, warum). Der Fortschritt ist gespeichert: Heben Sie den Alarm auf (Reset, Entsperren), prüfen Sie, dass der Stift dort steht, wo das Studio ihn zeigt, und drücken Sie dann Fortsetzen.</translation>
        </message>
        <message>
            <source>Resuming "%1"…</source>
            <translation>Setze „%1“ fort…</translation>
        </message>
        <message>
            <source>Running "%1"…</source>
            <translation>„%1“ läuft…</translation>
        </message>
        <message>
            <source>"%1" is drawn.</source>
            <translation>„%1“ ist gezeichnet.</translation>
        </message>
        <message>
            <source>Not started: %1</source>
            <translation>Nicht gestartet: %1</translation>
        </message>
        <message>
            <source>The run of "%1" was interrupted after %2: %3</source>
            <translation>Der Lauf von „%1“ wurde nach %2 unterbrochen: %3</translation>
        </message>
        <message>
            <source>The drawing, its placement, the machine profile or the tolerance changed since, so Resume would draw the old job where the canvas no longer shows it: undo the change to resume, or press Start to draw the new one from the beginning.</source>
            <translation>Die Zeichnung, ihre Platzierung, das Maschinenprofil oder die Toleranz haben sich seitdem geändert, Fortsetzen würde also den alten Auftrag dort zeichnen, wo die Arbeitsfläche ihn nicht mehr zeigt: die Änderung rückgängig machen, um fortzusetzen, oder Start drücken, um den neuen von vorn zu zeichnen.</translation>
        </message>
        <message>
            <source>Not started: the board's settings differ from the profile. %1 Write the profile's settings (Machine settings...), or choose Start anyway when Start asks.</source>
            <translation>Nicht gestartet: Die Einstellungen der Platine weichen vom Profil ab. %1 Die Einstellungen des Profils schreiben (Maschineneinstellungen …) oder bei der Nachfrage von Start „Trotzdem starten“ wählen.</translation>
        </message>
        <message>
            <source>Stopped before the first move: nothing was sent.</source>
            <translation>Vor der ersten Bewegung gestoppt: Nichts wurde gesendet.</translation>
        </message>
        <message>
            <source>Stopped after line %1 of %2; the pen is up and the machine at rest.</source>
            <translation>Nach Zeile %1 von %2 gestoppt; der Stift ist oben und die Maschine steht.</translation>
        </message>
        <message>
            <source>Stopped after line %1 of %2; the pen could not be lifted.</source>
            <translation>Nach Zeile %1 von %2 gestoppt; der Stift konnte nicht angehoben werden.</translation>
        </message>
        <message>
            <source>The progress is saved: press Resume to continue.</source>
            <translation>Der Fortschritt ist gespeichert: Fortsetzen drücken, um weiterzumachen.</translation>
        </message>
        <message>
            <source>Stopped after line %1 of %2: %3 The progress is saved: press Resume to continue.</source>
            <translation>Nach Zeile %1 von %2 gestoppt: %3 Der Fortschritt ist gespeichert: Fortsetzen drücken, um weiterzumachen.</translation>
        </message>
        <message>
            <source>Not resumed: the job is not planned yet; wait for the preview.</source>
            <translation>Nicht fortgesetzt: Der Auftrag ist noch nicht geplant; auf die Vorschau warten.</translation>
        </message>
        <message>
            <source>Not resumed: the drawing, its placement, the machine profile or the tolerance changed since the run was interrupted, so Resume would draw the old job where the canvas no longer shows it. Undo the change to resume, or press Start to draw the new one from the beginning.</source>
            <translation>Nicht fortgesetzt: Die Zeichnung, ihre Platzierung, das Maschinenprofil oder die Toleranz haben sich seit der Unterbrechung geändert, Fortsetzen würde also den alten Auftrag dort zeichnen, wo die Arbeitsfläche ihn nicht mehr zeigt. Die Änderung rückgängig machen, um fortzusetzen, oder Start drücken, um den neuen von vorn zu zeichnen.</translation>
        </message>
        <message>
            <source>Cannot resume: connect the machine and wait until it is idle.</source>
            <translation>Fortsetzen nicht möglich: die Maschine verbinden und warten, bis sie im Leerlauf ist.</translation>
        </message>
        <message>
            <source>Not resumed: %1</source>
            <translation>Nicht fortgesetzt: %1</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::OverrideControls</name>
        <message>
            <source>Overrides</source>
            <translation>Overrides</translation>
        </message>
        <message>
            <source>The machine scales the job's feed (10 to 200 %) and its rapid moves (25, 50 or 100 %) at once. It never exceeds its maximum rates ($110, $111): a higher feed override stops speeding up where the motors' limit is.</source>
            <translation>Die Maschine skaliert den Vorschub des Auftrags (10 bis 200 %) und seine Eilgänge (25, 50 oder 100 %) sofort. Sie überschreitet nie ihre Höchstgeschwindigkeiten ($110, $111): Ein höherer Vorschub-Override beschleunigt nur bis zur Grenze der Motoren.</translation>
        </message>
        <message>
            <source>Feed override: pen-down and other G1 moves</source>
            <translation>Vorschub-Override: Bewegungen mit abgesenktem Stift und andere G1-Bewegungen</translation>
        </message>
        <message>
            <source>Rapid override: G0 travel moves</source>
            <translation>Eilgang-Override: G0-Verfahrbewegungen</translation>
        </message>
        <message>
            <source>Feed</source>
            <translation>Vorschub</translation>
        </message>
        <message>
            <source>−10 %</source>
            <translation>−10 %</translation>
        </message>
        <message>
            <source>Alt+Down</source>
            <translation>Alt+Down</translation>
        </message>
        <message>
            <source>−1 %</source>
            <translation>−1 %</translation>
        </message>
        <message>
            <source>Alt+Left</source>
            <translation>Alt+Left</translation>
        </message>
        <message>
            <source>100 %</source>
            <translation>100 %</translation>
        </message>
        <message>
            <source>Alt+0</source>
            <translation>Alt+0</translation>
        </message>
        <message>
            <source>+1 %</source>
            <translation>+1 %</translation>
        </message>
        <message>
            <source>Alt+Right</source>
            <translation>Alt+Right</translation>
        </message>
        <message>
            <source>+10 %</source>
            <translation>+10 %</translation>
        </message>
        <message>
            <source>Alt+Up</source>
            <translation>Alt+Up</translation>
        </message>
        <message>
            <source>Rapid</source>
            <translation>Eilgang</translation>
        </message>
        <message>
            <source>25 %</source>
            <translation>25 %</translation>
        </message>
        <message>
            <source>Alt+4</source>
            <translation>Alt+4</translation>
        </message>
        <message>
            <source>50 %</source>
            <translation>50 %</translation>
        </message>
        <message>
            <source>Alt+2</source>
            <translation>Alt+2</translation>
        </message>
        <message>
            <source>Alt+1</source>
            <translation>Alt+1</translation>
        </message>
        <message>
            <source>%1 %</source>
            <translation>%1 %</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::RunPanel</name>
        <message>
            <source>Ready</source>
            <translation>Bereit</translation>
        </message>
        <message>
            <source>Running</source>
            <translation>Läuft</translation>
        </message>
        <message>
            <source>Holding…</source>
            <translation>Hält an…</translation>
        </message>
        <message>
            <source>On hold</source>
            <translation>Angehalten</translation>
        </message>
        <message>
            <source>Paused by a problem</source>
            <translation>Wegen eines Problems pausiert</translation>
        </message>
        <message>
            <source>Stopping…</source>
            <translation>Wird gestoppt…</translation>
        </message>
        <message>
            <source>Stopped</source>
            <translation>Gestoppt</translation>
        </message>
        <message>
            <source>Finished</source>
            <translation>Fertig</translation>
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
            <source>%1 s</source>
            <translation>%1 s</translation>
        </message>
        <message>
            <source>Start</source>
            <translation>Starten</translation>
        </message>
        <message>
            <source>Write the planned job as G-code and stream it to the machine</source>
            <translation>Den geplanten Auftrag als G-Code schreiben und an die Maschine senden</translation>
        </message>
        <message>
            <source>Hold</source>
            <translation>Anhalten</translation>
        </message>
        <message>
            <source>Feed hold: the machine decelerates and waits</source>
            <translation>Vorschub halten: Die Maschine bremst ab und wartet</translation>
        </message>
        <message>
            <source>Continue</source>
            <translation>Weiter</translation>
        </message>
        <message>
            <source>Continue after a hold</source>
            <translation>Nach dem Anhalten weitermachen</translation>
        </message>
        <message>
            <source>Stop</source>
            <translation>Stoppen</translation>
        </message>
        <message>
            <source>Stop the job: hold, reset and unlock; the progress is kept for a resume</source>
            <translation>Auftrag stoppen: anhalten, zurücksetzen und entsperren; der Fortschritt bleibt zum Fortsetzen erhalten</translation>
        </message>
        <message>
            <source>Resume</source>
            <translation>Fortsetzen</translation>
        </message>
        <message>
            <source>Continue the interrupted job from its last completed pen-down point, with a safe pen-up approach</source>
            <translation>Den unterbrochenen Auftrag ab seinem letzten fertigen Zeichenpunkt fortsetzen, mit sicherer Anfahrt bei angehobenem Stift</translation>
        </message>
        <message>
            <source>No job sent yet</source>
            <translation>Noch kein Auftrag gesendet</translation>
        </message>
        <message>
            <source>%1 left</source>
            <translation>noch %1</translation>
        </message>
        <message>
            <source>Long job</source>
            <translation>Langer Auftrag</translation>
        </message>
        <message>
            <source>Start from the beginning?</source>
            <translation>Von vorn beginnen?</translation>
        </message>
        <message>
            <source>%1

Start draws "%2" from the beginning and discards this saved progress. Resume continues the interrupted run instead.</source>
            <translation>%1

Start zeichnet „%2“ von vorn und verwirft diesen gespeicherten Fortschritt. Fortsetzen setzt stattdessen den unterbrochenen Lauf fort.</translation>
        </message>
        <message>
            <source>Discard and start over</source>
            <translation>Verwerfen und neu beginnen</translation>
        </message>
        <message>
            <source>Cancel</source>
            <translation>Abbrechen</translation>
        </message>
        <message>
            <source>Reading the board's settings to compare them with the profile: press Start again in a moment.</source>
            <translation>Die Einstellungen der Steuerung werden zum Vergleich mit dem Profil gelesen: Drücken Sie gleich noch einmal Start.</translation>
        </message>
        <message>
            <source>The board's settings differ</source>
            <translation>Die Einstellungen der Steuerung weichen ab</translation>
        </message>
        <message>
            <source>Write the profile's settings...</source>
            <translation>Einstellungen des Profils schreiben...</translation>
        </message>
        <message>
            <source>Start anyway</source>
            <translation>Trotzdem starten</translation>
        </message>
        <message>
            <source>%1 % (%2)</source>
            <translation>%1 % (%2)</translation>
        </message>
        <message>
            <source>%1 left (on hold)</source>
            <translation>noch %1 (angehalten)</translation>
        </message>
        <message>
            <source>Machine time left by the plan, planned again at the feed and rapid override the machine reports</source>
            <translation>Verbleibende Maschinenzeit laut Plan, neu geplant mit dem Vorschub- und Eilgang-Override, den die Maschine meldet</translation>
        </message>
    </context>
    <context>
        <name>fivebar::session::SettingsAdvice</name>
        <message>
            <source>soft limits are on, but this machine has no homing switches: the board measures its travel from where it was switched on, not from the reference pose, and stops the job with ALARM:2 when a move leaves that range.</source>
            <translation>Software-Endlagen sind an, aber diese Maschine hat keine Referenzschalter: Die Steuerung misst ihren Verfahrweg ab der Einschaltstellung, nicht ab der Referenzstellung, und stoppt den Auftrag mit ALARM:2, sobald eine Bewegung diesen Bereich verlässt.</translation>
        </message>
        <message>
            <source>soft limits are off although the profile expects them.</source>
            <translation>Software-Endlagen sind aus, obwohl das Profil sie erwartet.</translation>
        </message>
        <message>
            <source>hard limits are on: without limit switches wired, noise on the pins stops the machine with ALARM:1.</source>
            <translation>Hardware-Endlagen sind an: Ohne angeschlossene Endschalter stoppen Störungen an den Pins die Maschine mit ALARM:1.</translation>
        </message>
        <message>
            <source>hard limits are off although the profile expects them.</source>
            <translation>Hardware-Endlagen sind aus, obwohl das Profil sie erwartet.</translation>
        </message>
        <message>
            <source>the homing cycle is on: the board starts locked and wants $H, which needs homing switches.</source>
            <translation>Der Referenzlauf ist an: Die Steuerung startet gesperrt und verlangt $H, wofür Referenzschalter nötig sind.</translation>
        </message>
        <message>
            <source>the homing cycle is off although the profile has switches.</source>
            <translation>Der Referenzlauf ist aus, obwohl das Profil Schalter hat.</translation>
        </message>
        <message>
            <source>steps per degree differ: every motor angle would be wrong by the ratio, so the arms would leave the checked, safe poses.</source>
            <translation>Die Schritte pro Grad weichen ab: Jeder Motorwinkel wäre um dieses Verhältnis falsch, die Arme verließen also die geprüften, sicheren Stellungen.</translation>
        </message>
        <message>
            <source>the board's maximum rate is lower: the job runs slower than planned and the time estimate is off.</source>
            <translation>Die Höchstgeschwindigkeit der Steuerung ist niedriger: Der Auftrag läuft langsamer als geplant und die Zeitschätzung stimmt nicht.</translation>
        </message>
        <message>
            <source>the board's maximum rate is higher than the profile allows: the motors may lose steps.</source>
            <translation>Die Höchstgeschwindigkeit der Steuerung ist höher, als das Profil erlaubt: Die Motoren können Schritte verlieren.</translation>
        </message>
        <message>
            <source>the board accelerates more gently: the job takes longer than planned.</source>
            <translation>Die Steuerung beschleunigt sanfter: Der Auftrag dauert länger als geplant.</translation>
        </message>
        <message>
            <source>the board accelerates harder than the profile allows: the motors may lose steps.</source>
            <translation>Die Steuerung beschleunigt stärker, als das Profil erlaubt: Die Motoren können Schritte verlieren.</translation>
        </message>
        <message>
            <source>the motor's travel for soft limits differs: with soft limits on, a move beyond it stops the job with ALARM:2.</source>
            <translation>Der Verfahrweg des Motors für die Software-Endlagen weicht ab: Mit Software-Endlagen stoppt eine Bewegung darüber hinaus den Auftrag mit ALARM:2.</translation>
        </message>
        <message>
            <source>the spindle (pen servo / laser) range differs: the pen may not lift or lower as planned.</source>
            <translation>Der Spindelbereich (Stiftservo / Laser) weicht ab: Der Stift hebt oder senkt sich womöglich nicht wie geplant.</translation>
        </message>
        <message>
            <source>the junction deviation differs: corners run at other speeds than planned.</source>
            <translation>Die Eckenabweichung weicht ab: Ecken werden mit anderen Geschwindigkeiten als geplant gefahren.</translation>
        </message>
        <message>
            <source>differs from what the profile expects.</source>
            <translation>weicht von dem ab, was das Profil erwartet.</translation>
        </message>
        <message>
            <source>not reported</source>
            <translation>nicht gemeldet</translation>
        </message>
        <message>
            <source>$%1 is %2 on the board, the profile wants %3: %4</source>
            <translation>$%1 ist auf der Steuerung %2, das Profil will %3: %4</translation>
        </message>
        <message numerus="yes">
            <source>The board's settings differ from the profile in %n place(s): %1.</source>
            <translation>
                <numerusform>Die Einstellungen der Steuerung weichen an %n Stelle vom Profil ab: %1.</numerusform>
                <numerusform>Die Einstellungen der Steuerung weichen an %n Stellen vom Profil ab: %1.</numerusform>
            </translation>
        </message>
        <message>
            <source>A job would stop or move wrongly with them.</source>
            <translation>Ein Auftrag würde damit stoppen oder falsch fahren.</translation>
        </message>
        <message>
            <source>The board's GRBL settings differ from the machine profile, and the job would not run as planned:</source>
            <translation>Die GRBL-Einstellungen der Steuerung weichen vom Maschinenprofil ab, und der Auftrag liefe nicht wie geplant:</translation>
        </message>
        <message>
            <source>The board's GRBL settings differ from the machine profile:</source>
            <translation>Die GRBL-Einstellungen der Steuerung weichen vom Maschinenprofil ab:</translation>
        </message>
        <message>
            <source>Write the profile's settings to the board (its current ones are saved to a backup file first), or start anyway.</source>
            <translation>Schreiben Sie die Einstellungen des Profils auf die Steuerung (die aktuellen werden vorher in einer Sicherungsdatei gespeichert), oder starten Sie trotzdem.</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::SimulationPanel</name>
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
            <source>&lt;table&gt;&lt;tr&gt;&lt;td&gt;Motor angles:&lt;/td&gt;&lt;td&gt;%1 deg, %2 deg&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;Pen:&lt;/td&gt;&lt;td&gt;x %3 mm, y %4 mm (%5)&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;Transmission angle:&lt;/td&gt;&lt;td&gt;%6 deg at the pen&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;/td&gt;&lt;td&gt;%7 / %8 deg at the elbows&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;Type II margin:&lt;/td&gt;&lt;td&gt;&lt;b&gt;%9 deg&lt;/b&gt;&lt;/td&gt;&lt;/tr&gt;&lt;/table&gt;</source>
            <translation>&lt;table&gt;&lt;tr&gt;&lt;td&gt;Motorwinkel:&lt;/td&gt;&lt;td&gt;%1 Grad, %2 Grad&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;Stift:&lt;/td&gt;&lt;td&gt;x %3 mm, y %4 mm (%5)&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;Übertragungswinkel:&lt;/td&gt;&lt;td&gt;%6 Grad am Stift&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;/td&gt;&lt;td&gt;%7 / %8 Grad an den Ellbogen&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;Abstand Typ II:&lt;/td&gt;&lt;td&gt;&lt;b&gt;%9 Grad&lt;/b&gt;&lt;/td&gt;&lt;/tr&gt;&lt;/table&gt;</translation>
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
        <name>fivebar::widgets::SpeedLegend</name>
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
        <name>fivebar::widgets::StudioDocument</name>
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
        <message>
            <source>Change layer fill</source>
            <translation>Füllung der Ebene ändern</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::calibration::AccuracyPage</name>
        <message>
            <source>Measure the accuracy lines</source>
            <translation>Die Genauigkeitslinien messen</translation>
        </message>
        <message>
            <source>Hoang's accuracy pattern is ten lines, each meant to be 40 mm long and straight, 10 mm apart. Lay a steel ruler along each line. &lt;b&gt;Length&lt;/b&gt;: from end to end, in the middle of the pen's stroke. &lt;b&gt;Straightness&lt;/b&gt;: the widest gap between the line and the ruler's edge when the ruler touches both ends (0 for a straight line). Type the lines drawn &lt;b&gt;before&lt;/b&gt; calibration in the first two columns and those of the verification sheet (drawn &lt;b&gt;after&lt;/b&gt;) in the last two; the figures below compare them.</source>
            <translation>Hoangs Genauigkeitsmuster sind zehn Linien, jede soll 40 mm lang und gerade sein, 10 mm auseinander. Legen Sie ein Stahllineal an jede Linie. &lt;b&gt;Länge&lt;/b&gt;: von Ende zu Ende, in der Mitte des Stiftstrichs. &lt;b&gt;Geradheit&lt;/b&gt;: der größte Spalt zwischen Linie und Linealkante, wenn das Lineal beide Enden berührt (0 für eine gerade Linie). Tippen Sie die Linien, die &lt;b&gt;vor&lt;/b&gt; der Kalibrierung gezeichnet wurden, in die ersten beiden Spalten und die des Prüfblatts (&lt;b&gt;danach&lt;/b&gt; gezeichnet) in die letzten beiden; die Werte darunter vergleichen sie.</translation>
        </message>
        <message>
            <source>Length before (mm)</source>
            <translation>Länge vorher (mm)</translation>
        </message>
        <message>
            <source>Straightness before (mm)</source>
            <translation>Geradheit vorher (mm)</translation>
        </message>
        <message>
            <source>Length after (mm)</source>
            <translation>Länge nachher (mm)</translation>
        </message>
        <message>
            <source>Straightness after (mm)</source>
            <translation>Geradheit nachher (mm)</translation>
        </message>
        <message>
            <source>Line %1</source>
            <translation>Linie %1</translation>
        </message>
        <message>
            <source>Simulation: measure the simulated lines</source>
            <translation>Simulation: die simulierten Linien messen</translation>
        </message>
        <message>
            <source>Fills the table with the lines as the simulated imperfect machine draws them: before with the profile the wizard started from, after with the calibrated profile.</source>
            <translation>Füllt die Tabelle mit den Linien, wie die simulierte unvollkommene Maschine sie zeichnet: vorher mit dem Profil, mit dem der Assistent begann, nachher mit dem kalibrierten Profil.</translation>
        </message>
        <message>
            <source>Line %1, %2: '%3' is not a length in mm.</source>
            <translation>Linie %1, %2: „%3“ ist keine Länge in mm.</translation>
        </message>
        <message>
            <source>&lt;b&gt;%1:&lt;/b&gt; not measured yet (type a length and a straightness per line).</source>
            <translation>&lt;b&gt;%1:&lt;/b&gt; noch nicht gemessen (tippen Sie je Linie eine Länge und eine Geradheit ein).</translation>
        </message>
        <message>
            <source>&lt;b&gt;%1:&lt;/b&gt; straightness %2 mm at worst (RMS %3 mm); length off by %4 mm at worst (RMS %5 mm), over %6 lines.</source>
            <translation>&lt;b&gt;%1:&lt;/b&gt; Geradheit schlechtestens %2 mm (RMS %3 mm); Länge schlechtestens %4 mm daneben (RMS %5 mm), über %6 Linien.</translation>
        </message>
        <message>
            <source>Before calibration</source>
            <translation>Vor der Kalibrierung</translation>
        </message>
        <message>
            <source>After calibration</source>
            <translation>Nach der Kalibrierung</translation>
        </message>
        <message>
            <source>&lt;br&gt;Worst straightness plus worst length error: %1 mm &amp;rarr; &lt;b&gt;%2 mm&lt;/b&gt;.</source>
            <translation>&lt;br&gt;Schlechteste Geradheit plus schlechtester Längenfehler: %1 mm &amp;rarr; &lt;b&gt;%2 mm&lt;/b&gt;.</translation>
        </message>
        <message>
            <source>&lt;br&gt;&lt;i&gt;Apply the calibration (step 5) to see the lines drawn after it.&lt;/i&gt;</source>
            <translation>&lt;br&gt;&lt;i&gt;Wenden Sie die Kalibrierung an (Schritt 5), um die danach gezeichneten Linien zu sehen.&lt;/i&gt;</translation>
        </message>
        <message>
            <source>Import scan...</source>
            <translation>Scan importieren...</translation>
        </message>
        <message>
            <source>A scan of the sheet with the accuracy lines (PNG or JPEG, taken straight from above): each line's length and straightness are measured in the image and fill the columns of the chosen sheet.</source>
            <translation>Ein Scan des Blatts mit den Genauigkeitslinien (PNG oder JPEG, gerade von oben aufgenommen): Länge und Geradheit jeder Linie werden im Bild gemessen und füllen die Spalten des gewählten Blatts.</translation>
        </message>
        <message>
            <source>Sheet drawn before calibration</source>
            <translation>Blatt vor der Kalibrierung gezeichnet</translation>
        </message>
        <message>
            <source>Sheet drawn after calibration</source>
            <translation>Blatt nach der Kalibrierung gezeichnet</translation>
        </message>
        <message>
            <source> dpi</source>
            <translation> dpi</translation>
        </message>
        <message>
            <source>The scanner's resolution: the scan's size in mm comes from it.</source>
            <translation>Die Auflösung des Scanners: aus ihr ergibt sich die Größe des Scans in mm.</translation>
        </message>
        <message>
            <source>Import a scan of the accuracy lines</source>
            <translation>Einen Scan der Genauigkeitslinien importieren</translation>
        </message>
        <message>
            <source>Images (*.png *.jpg *.jpeg *.tif *.tiff *.bmp)</source>
            <translation>Bilder (*.png *.jpg *.jpeg *.tif *.tiff *.bmp)</translation>
        </message>
        <message>
            <source>A line in the scan is too short to measure.</source>
            <translation>Eine Linie im Scan ist zu kurz zum Messen.</translation>
        </message>
        <message>
            <source>Found %1 lines in the scan (%2 mm pen): the %3 columns are filled.</source>
            <translation>%1 Linien im Scan gefunden (Stift %2 mm): die Spalten „%3“ sind ausgefüllt.</translation>
        </message>
        <message>
            <source>after</source>
            <translation>nachher</translation>
        </message>
        <message>
            <source>before</source>
            <translation>vorher</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::calibration::ApplyPage</name>
        <message>
            <source>5. Apply the calibration to the profile</source>
            <translation>5. Die Kalibrierung ins Profil übernehmen</translation>
        </message>
        <message>
            <source>Applying writes the fitted link lengths into the profile and keeps the motor zeros and the backlash in its calibration section. From then on every plan, jog and check uses them. &lt;b&gt;Edit &amp;gt; Undo&lt;/b&gt; takes it back; the profile is saved with the project, and you can also save it as a profile file for other projects.</source>
            <translation>Beim Übernehmen kommen die ermittelten Gliedlängen ins Profil, die Motornullpunkte und das Umkehrspiel in seinen Kalibrierabschnitt. Ab dann verwenden jede Planung, jedes Verfahren und jede Prüfung diese Werte. &lt;b&gt;Bearbeiten &amp;gt; Rückgängig&lt;/b&gt; nimmt es zurück; das Profil wird mit dem Projekt gespeichert, und Sie können es auch als Profildatei für andere Projekte speichern.</translation>
        </message>
        <message>
            <source>Apply to the profile</source>
            <translation>Ins Profil übernehmen</translation>
        </message>
        <message>
            <source>Save profile as...</source>
            <translation>Profil speichern unter...</translation>
        </message>
        <message>
            <source>Save the calibrated profile</source>
            <translation>Das kalibrierte Profil speichern</translation>
        </message>
        <message>
            <source>Machine profile (*.json)</source>
            <translation>Maschinenprofil (*.json)</translation>
        </message>
        <message>
            <source>Saved %1.</source>
            <translation>%1 gespeichert.</translation>
        </message>
        <message>
            <source> mm</source>
            <translation> mm</translation>
        </message>
        <message>
            <source>°</source>
            <translation>°</translation>
        </message>
        <message>
            <source>motor 1 zero</source>
            <translation>Nullpunkt Motor 1</translation>
        </message>
        <message>
            <source>motor 2 zero</source>
            <translation>Nullpunkt Motor 2</translation>
        </message>
        <message>
            <source>motor 1 backlash</source>
            <translation>Umkehrspiel Motor 1</translation>
        </message>
        <message>
            <source>motor 2 backlash</source>
            <translation>Umkehrspiel Motor 2</translation>
        </message>
        <message>
            <source>Applied. Edit &gt; Undo restores the profile as it was.</source>
            <translation>Übernommen. Bearbeiten &gt; Rückgängig stellt das alte Profil wieder her.</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::calibration::CalibrationPreview</name>
        <message>
            <source>No pattern yet</source>
            <translation>Noch kein Muster</translation>
        </message>
        <message>
            <source>pattern as planned</source>
            <translation>Muster wie geplant</translation>
        </message>
        <message>
            <source>drawn by the pen (simulation)</source>
            <translation>vom Stift gezeichnet (Simulation)</translation>
        </message>
        <message>
            <source>measured</source>
            <translation>gemessen</translation>
        </message>
        <message>
            <source>error before</source>
            <translation>Fehler vorher</translation>
        </message>
        <message>
            <source>error after</source>
            <translation>Fehler nachher</translation>
        </message>
        <message>
            <source>arrows ×%1</source>
            <translation>Pfeile ×%1</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::calibration::CalibrationWizard</name>
        <message>
            <source>The pattern is already being drawn.</source>
            <translation>Das Muster wird bereits gezeichnet.</translation>
        </message>
        <message>
            <source>Connect a machine (or the simulated machine) in the Machine panel first, and let any running job finish.</source>
            <translation>Verbinden Sie zuerst eine Maschine (oder die simulierte Maschine) in der Maschinen-Leiste, und lassen Sie einen laufenden Auftrag zu Ende laufen.</translation>
        </message>
        <message>
            <source>Calibrate the machine</source>
            <translation>Die Maschine kalibrieren</translation>
        </message>
        <message>
            <source>&amp;Calibrate...</source>
            <translation>&amp;Kalibrieren...</translation>
        </message>
        <message>
            <source>Measure a drawn pattern and correct the profile's link lengths and motor zeros</source>
            <translation>Ein gezeichnetes Muster vermessen und die Gliedlängen und Motornullpunkte des Profils korrigieren</translation>
        </message>
        <message>
            <source>Choose a pattern first.</source>
            <translation>Wählen Sie zuerst ein Muster.</translation>
        </message>
        <message>
            <source>The pattern cannot be planned: %1</source>
            <translation>Das Muster lässt sich nicht planen: %1</translation>
        </message>
        <message>
            <source>The pattern's G-code cannot be written: %1</source>
            <translation>Der G-Code des Musters lässt sich nicht schreiben: %1</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::calibration::DistancesBox</name>
        <message>
            <source>Only a ruler? Measure the distance between the centres of two marks and type both mark numbers and the distance. No corner or direction is needed. Measure long and short pairs across the whole sheet, each mark in several pairs: about four per mark (100 for 25 marks) calibrate as well as coordinates. Use the marks for the fit, not the backlash rows.</source>
            <translation>Nur ein Lineal? Messen Sie den Abstand zwischen den Mitten zweier Marken und tippen Sie beide Markennummern und den Abstand ein. Keine Ecke und keine Richtung nötig. Messen Sie lange und kurze Paare über das ganze Blatt, jede Marke in mehreren Paaren: etwa vier je Marke (100 für 25 Marken) kalibrieren so gut wie Koordinaten. Nehmen Sie die Marken für den Fit, nicht die Spiel-Reihen.</translation>
        </message>
        <message>
            <source>Mark A</source>
            <translation>Marke A</translation>
        </message>
        <message>
            <source>Mark B</source>
            <translation>Marke B</translation>
        </message>
        <message>
            <source>Distance (mm)</source>
            <translation>Abstand (mm)</translation>
        </message>
        <message>
            <source>Add a row</source>
            <translation>Zeile hinzufügen</translation>
        </message>
        <message>
            <source>Remove the row</source>
            <translation>Zeile entfernen</translation>
        </message>
        <message>
            <source>Load distances CSV...</source>
            <translation>Abstände-CSV laden...</translation>
        </message>
        <message>
            <source>A file with the columns id_a,id_b,distance_mm (as fivebar calibrate fit reads it)</source>
            <translation>Eine Datei mit den Spalten id_a,id_b,distance_mm (wie fivebar calibrate fit sie liest)</translation>
        </message>
        <message>
            <source>Simulation: measure distances on the simulated sheet</source>
            <translation>Simulation: Abstände auf dem simulierten Blatt messen</translation>
        </message>
        <message>
            <source>Fills the table with distances between where the simulated imperfect machine put the marks, plus ruler noise.</source>
            <translation>Füllt die Tabelle mit Abständen zwischen den Stellen, an die die simulierte unvollkommene Maschine die Marken setzte, plus Linealrauschen.</translation>
        </message>
        <message>
            <source>noise ±</source>
            <translation>Rauschen ±</translation>
        </message>
        <message>
            <source> mm</source>
            <translation> mm</translation>
        </message>
        <message>
            <source>Load distances</source>
            <translation>Abstände laden</translation>
        </message>
        <message>
            <source>CSV (*.csv)</source>
            <translation>CSV (*.csv)</translation>
        </message>
        <message>
            <source>Filled from the simulated sheet (simulation, not a measurement).</source>
            <translation>Aus dem simulierten Blatt gefüllt (Simulation, keine Messung).</translation>
        </message>
        <message>
            <source>mark A</source>
            <translation>Marke A</translation>
        </message>
        <message>
            <source>mark B</source>
            <translation>Marke B</translation>
        </message>
        <message>
            <source>distance</source>
            <translation>Abstand</translation>
        </message>
        <message>
            <source>Row %1: %2 is empty.</source>
            <translation>Zeile %1: %2 ist leer.</translation>
        </message>
        <message>
            <source>Row %1, %2: '%3' is not a number.</source>
            <translation>Zeile %1, %2: „%3“ ist keine Zahl.</translation>
        </message>
        <message>
            <source>Row %1: there is no mark %2 in the pattern.</source>
            <translation>Zeile %1: Marke %2 gibt es im Muster nicht.</translation>
        </message>
        <message>
            <source>Row %1: mark %2 is in a backlash row; measure distances between marks for the fit.</source>
            <translation>Zeile %1: Marke %2 gehört zu einer Spiel-Reihe; messen Sie Abstände zwischen Marken für den Fit.</translation>
        </message>
        <message>
            <source>Row %1: a distance from mark %2 to itself.</source>
            <translation>Zeile %1: ein Abstand von Marke %2 zu sich selbst.</translation>
        </message>
        <message>
            <source>Row %1: the distance must be more than 0 mm.</source>
            <translation>Zeile %1: der Abstand muss größer als 0 mm sein.</translation>
        </message>
        <message>
            <source>%1 holds mark coordinates, not distances: load it in the Coordinates tab.</source>
            <translation>%1 enthält Markenkoordinaten, keine Abstände: laden Sie sie im Reiter Koordinaten.</translation>
        </message>
        <message>
            <source>%1:%2: the pattern's marks are numbered; '%3' is not a mark number.</source>
            <translation>%1:%2: die Marken des Musters sind nummeriert; „%3“ ist keine Markennummer.</translation>
        </message>
        <message>
            <source>Loaded %1 distances from %2.</source>
            <translation>%1 Abstände aus %2 geladen.</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::calibration::DrawPage</name>
        <message>
            <source>2. Draw the pattern</source>
            <translation>2. Das Muster zeichnen</translation>
        </message>
        <message>
            <source>Tape a sheet down so it cannot move, and draw the pattern with the pen you normally use. Draw it on the connected machine, or export its G-code and send it your way. Keep MARKS.csv: it says which motor angles drew each mark.</source>
            <translation>Kleben Sie ein Blatt fest, damit es nicht verrutscht, und zeichnen Sie das Muster mit dem Stift, den Sie sonst auch benutzen. Zeichnen Sie es auf der verbundenen Maschine, oder exportieren Sie den G-Code und senden Sie ihn auf Ihre Weise. Heben Sie MARKS.csv auf: Dort steht, mit welchen Motorwinkeln jede Marke gezeichnet wurde.</translation>
        </message>
        <message>
            <source>Draw on the connected machine</source>
            <translation>Auf der verbundenen Maschine zeichnen</translation>
        </message>
        <message>
            <source>Export G-code...</source>
            <translation>G-Code exportieren...</translation>
        </message>
        <message>
            <source>Export MARKS.csv...</source>
            <translation>MARKS.csv exportieren...</translation>
        </message>
        <message>
            <source>No hardware? Simulate an imperfect machine</source>
            <translation>Keine Hardware? Eine unvollkommene Maschine simulieren</translation>
        </message>
        <message>
            <source>Simulate an imperfect machine (the sheet below is what it draws)</source>
            <translation>Eine unvollkommene Maschine simulieren (das Blatt unten zeigt, was sie zeichnet)</translation>
        </message>
        <message>
            <source>The pattern is drawn. Take the sheet off and measure it.</source>
            <translation>Das Muster ist gezeichnet. Nehmen Sie das Blatt ab und vermessen Sie es.</translation>
        </message>
        <message>
            <source>Drawing the pattern (%1 lines of G-code)...</source>
            <translation>Das Muster wird gezeichnet (%1 Zeilen G-Code)...</translation>
        </message>
        <message>
            <source>Export the pattern's G-code</source>
            <translation>Den G-Code des Musters exportieren</translation>
        </message>
        <message>
            <source>G-code (*.gcode *.nc)</source>
            <translation>G-Code (*.gcode *.nc)</translation>
        </message>
        <message>
            <source>Wrote %1.</source>
            <translation>%1 geschrieben.</translation>
        </message>
        <message>
            <source>Export MARKS.csv</source>
            <translation>MARKS.csv exportieren</translation>
        </message>
        <message>
            <source>CSV (*.csv)</source>
            <translation>CSV (*.csv)</translation>
        </message>
        <message>
            <source>Streams the pattern with the same checks as the Run panel</source>
            <translation>Sendet das Muster mit denselben Prüfungen wie die Ausführen-Leiste</translation>
        </message>
        <message>
            <source>Connect a machine or the simulated machine in the Machine panel first</source>
            <translation>Verbinden Sie zuerst eine Maschine oder die simulierte Maschine in der Maschinen-Leiste</translation>
        </message>
        <message>
            <source>The simulated machine differs from the profile by these amounts, as a real one would. The picture shows what its pen really draws (orange) beside the plan. The built-in simulated machine (Machine panel) becomes this machine at once, also when it is connected. When the wizard closes it goes back to the studio's setting (Machine &amp;gt; Simulated machine...), unless you keep it.</source>
            <translation>Die simulierte Maschine weicht um diese Werte vom Profil ab, wie eine echte es täte. Das Bild zeigt, was ihr Stift wirklich zeichnet (orange), neben dem Plan. Die eingebaute simulierte Maschine (Maschinen-Panel) wird sofort zu dieser Maschine, auch wenn sie verbunden ist. Wenn der Assistent schließt, gilt wieder die Einstellung des Studios (Maschine &amp;gt; Simulierte Maschine...), außer Sie behalten sie.</translation>
        </message>
        <message>
            <source>Keep this machine as the studio's simulated machine after the wizard</source>
            <translation>Diese Maschine nach dem Assistenten als simulierte Maschine des Studios behalten</translation>
        </message>
        <message>
            <source>Saved in Machine &gt; Simulated machine...; the status bar shows it while it is imperfect</source>
            <translation>Gespeichert unter Maschine &gt; Simulierte Maschine...; die Statusleiste zeigt sie, solange sie unvollkommen ist</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::calibration::FitPage</name>
        <message>
            <source>4. Fit the machine to the marks</source>
            <translation>4. Die Maschine an die Marken anpassen</translation>
        </message>
        <message>
            <source>The fit looks for the link lengths and motor zeros with which the machine would have put every mark where you measured it. Some marks are kept out of the fit and only used to check it afterwards ("held out"): their error is the honest one. The arrows show each mark's error, greatly enlarged: grey before, red after.</source>
            <translation>Die Anpassung sucht die Gliedlängen und Motornullpunkte, mit denen die Maschine jede Marke dorthin gesetzt hätte, wo Sie sie gemessen haben. Einige Marken bleiben aus der Anpassung heraus und dienen nur der Kontrolle danach („zurückgehalten“): Ihr Fehler ist der ehrliche. Die Pfeile zeigen den Fehler jeder Marke, stark vergrößert: grau vorher, rot nachher.</translation>
        </message>
        <message>
            <source>Parameter</source>
            <translation>Parameter</translation>
        </message>
        <message>
            <source>Profile</source>
            <translation>Profil</translation>
        </message>
        <message>
            <source>Fitted ± std. dev.</source>
            <translation>Angepasst ± Std.-Abw.</translation>
        </message>
        <message>
            <source>&lt;span style='color:#b00000'&gt;&lt;b&gt;The fit failed:&lt;/b&gt; %1&lt;/span&gt;&lt;br&gt;Go back, check the table, or measure more marks.</source>
            <translation>&lt;span style='color:#b00000'&gt;&lt;b&gt;Die Anpassung ist fehlgeschlagen:&lt;/b&gt; %1&lt;/span&gt;&lt;br&gt;Gehen Sie zurück, prüfen Sie die Tabelle oder messen Sie mehr Marken.</translation>
        </message>
        <message>
            <source>Backlash from %1 + %2 rows: motor 1 %3°, motor 2 %4°.</source>
            <translation>Umkehrspiel aus %1 + %2 Reihen: Motor 1 %3°, Motor 2 %4°.</translation>
        </message>
        <message>
            <source>Backlash not measured: %1</source>
            <translation>Umkehrspiel nicht gemessen: %1</translation>
        </message>
        <message>
            <source>No mark looks mis-measured.</source>
            <translation>Keine Marke scheint falsch gemessen.</translation>
        </message>
        <message>
            <source>&lt;span style='color:#b00000'&gt;Left out as mis-measured: mark %1. Check it on the sheet.&lt;/span&gt;</source>
            <translation>&lt;span style='color:#b00000'&gt;Als falsch gemessen weggelassen: Marke %1. Prüfen Sie sie auf dem Blatt.&lt;/span&gt;</translation>
        </message>
        <message>
            <source>°</source>
            <translation>°</translation>
        </message>
        <message>
            <source> mm</source>
            <translation> mm</translation>
        </message>
        <message>
            <source>%1 ± %2%3</source>
            <translation>%1 ± %2%3</translation>
        </message>
        <message>
            <source>Backlash is not measured from distances (it needs the positions of the backlash rows' marks); the profile's backlash is kept.</source>
            <translation>Das Spiel wird aus Abständen nicht gemessen (dazu braucht es die Lagen der Marken der Spiel-Reihen); das Spiel des Profils bleibt.</translation>
        </message>
        <message>
            <source>&lt;span style='color:#b00000'&gt;Left out as mis-measured: distance %1 (marks A-B). Measure it again.&lt;/span&gt;</source>
            <translation>&lt;span style='color:#b00000'&gt;Als falsch gemessen weggelassen: Abstand %1 (Marken A-B). Messen Sie ihn noch einmal.&lt;/span&gt;</translation>
        </message>
        <message>
            <source>&lt;b&gt;Distance error before: %1 mm RMS&lt;/b&gt; (largest %2 mm) &amp;rarr; &lt;b&gt;after: %3 mm RMS&lt;/b&gt; (largest %4 mm) over %5 distances.</source>
            <translation>&lt;b&gt;Abstandsfehler vorher: %1 mm RMS&lt;/b&gt; (größter %2 mm) &amp;rarr; &lt;b&gt;nachher: %3 mm RMS&lt;/b&gt; (größter %4 mm) über %5 Abstände.</translation>
        </message>
        <message>
            <source>&lt;b&gt;Error before: %1 mm RMS&lt;/b&gt; (largest %2 mm) &amp;rarr; &lt;b&gt;after: %3 mm RMS&lt;/b&gt; (largest %4 mm) over %5 marks.</source>
            <translation>&lt;b&gt;Fehler vorher: %1 mm RMS&lt;/b&gt; (größter %2 mm) &amp;rarr; &lt;b&gt;nachher: %3 mm RMS&lt;/b&gt; (größter %4 mm) über %5 Marken.</translation>
        </message>
        <message>
            <source>&lt;br&gt;Held-out measurements (%1): %2 mm before &amp;rarr; %3 mm after.&lt;br&gt;%4&lt;br&gt;%5&lt;br&gt;&lt;small&gt;Condition number %6 (below 10000 is fine).&lt;/small&gt;</source>
            <translation>&lt;br&gt;Zurückgehaltene Messungen (%1): %2 mm vorher &amp;rarr; %3 mm nachher.&lt;br&gt;%4&lt;br&gt;%5&lt;br&gt;&lt;small&gt;Konditionszahl %6 (unter 10000 ist gut).&lt;/small&gt;</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::calibration::MeasurePage</name>
        <message>
            <source>3. Measure the marks</source>
            <translation>3. Die Marken vermessen</translation>
        </message>
        <message>
            <source>Mark</source>
            <translation>Marke</translation>
        </message>
        <message>
            <source>Kind</source>
            <translation>Art</translation>
        </message>
        <message>
            <source>x (mm)</source>
            <translation>x (mm)</translation>
        </message>
        <message>
            <source>y (mm)</source>
            <translation>y (mm)</translation>
        </message>
        <message>
            <source>Simulation: measure the simulated sheet</source>
            <translation>Simulation: das simulierte Blatt vermessen</translation>
        </message>
        <message>
            <source>Fills the table with where the simulated imperfect machine put each mark, plus ruler noise. For trying the wizard without hardware.</source>
            <translation>Füllt die Tabelle mit den Stellen, an die die simulierte unvollkommene Maschine jede Marke gesetzt hat, plus Messrauschen. Zum Ausprobieren des Assistenten ohne Hardware.</translation>
        </message>
        <message>
            <source>noise ±</source>
            <translation>Rauschen ±</translation>
        </message>
        <message>
            <source> mm</source>
            <translation> mm</translation>
        </message>
        <message>
            <source>Import a scan...</source>
            <translation>Scan importieren...</translation>
        </message>
        <message>
            <source>A scan or photo taken straight from above (PNG or JPEG): the marks are found and numbered by themselves.</source>
            <translation>Ein Scan oder ein gerade von oben aufgenommenes Foto (PNG oder JPEG): Die Marken werden von selbst gefunden und nummeriert.</translation>
        </message>
        <message>
            <source> dpi</source>
            <translation> dpi</translation>
        </message>
        <message>
            <source>The scanner's resolution: the scan's size in mm comes from it.</source>
            <translation>Die Auflösung des Scanners: Aus ihr ergibt sich die Größe des Scans in mm.</translation>
        </message>
        <message>
            <source>Load MEASURED.csv...</source>
            <translation>MEASURED.csv laden...</translation>
        </message>
        <message>
            <source>Save MEASURED.csv...</source>
            <translation>MEASURED.csv speichern...</translation>
        </message>
        <message>
            <source>Import a scan of the sheet</source>
            <translation>Einen Scan des Blatts importieren</translation>
        </message>
        <message>
            <source>Images (*.png *.jpg *.jpeg *.tif *.tiff *.bmp)</source>
            <translation>Bilder (*.png *.jpg *.jpeg *.tif *.tiff *.bmp)</translation>
        </message>
        <message>
            <source>Load MEASURED.csv</source>
            <translation>MEASURED.csv laden</translation>
        </message>
        <message>
            <source>CSV (*.csv)</source>
            <translation>CSV (*.csv)</translation>
        </message>
        <message>
            <source>Save MEASURED.csv</source>
            <translation>MEASURED.csv speichern</translation>
        </message>
        <message>
            <source>fit</source>
            <translation>Anpassung</translation>
        </message>
        <message>
            <source>backlash %1</source>
            <translation>Umkehrspiel %1</translation>
        </message>
        <message>
            <source>Filled from the simulated sheet (simulation, not a measurement).</source>
            <translation>Aus dem simulierten Blatt gefüllt (Simulation, keine Messung).</translation>
        </message>
        <message>
            <source>Mark %1: %2 is empty. Type both x and y, or leave both empty.</source>
            <translation>Marke %1: %2 ist leer. Tippen Sie x und y ein, oder lassen Sie beide leer.</translation>
        </message>
        <message>
            <source>Mark %1, %2: '%3' is not a number.</source>
            <translation>Marke %1, %2: „%3“ ist keine Zahl.</translation>
        </message>
        <message>
            <source>Only %1 marks for the fit are measured; measure at least %2 (the fit finds 5 lengths, 2 motor zeros and how the sheet lay).</source>
            <translation>Nur %1 Marken für die Anpassung sind gemessen; messen Sie mindestens %2 (die Anpassung bestimmt 5 Längen, 2 Motornullpunkte und die Lage des Blatts).</translation>
        </message>
        <message>
            <source>Cannot read %1: %2</source>
            <translation>%1 kann nicht gelesen werden: %2</translation>
        </message>
        <message>
            <source>Found %1 of %2 marks in the scan (sheet turned %3°%4).%5</source>
            <translation>%1 von %2 Marken im Scan gefunden (Blatt um %3° gedreht%4).%5</translation>
        </message>
        <message>
            <source>, mirrored</source>
            <translation>, gespiegelt</translation>
        </message>
        <message>
            <source> Not found: %1; type them in by hand.</source>
            <translation> Nicht gefunden: %1; tippen Sie sie von Hand ein.</translation>
        </message>
        <message>
            <source>Cannot write %1: %2</source>
            <translation>%1 kann nicht geschrieben werden: %2</translation>
        </message>
        <message>
            <source>Measure the centre of each numbered dot with a ruler and type its x and y in millimetres. Any corner of the sheet can be the origin, and y may point up or down: the fit finds how the sheet lay. The mark you are typing is circled on the picture. Leave a row empty if a mark cannot be read; a mis-measured mark is found and named by the fit. With a scanner, import a scan instead: the marks are found and numbered for you. With a ruler alone, measure distances between marks in the second tab.</source>
            <translation>Messen Sie die Mitte jedes nummerierten Punkts mit einem Lineal und tippen Sie x und y in Millimetern ein. Jede Ecke des Blatts kann der Ursprung sein, und y darf nach oben oder unten zeigen: der Fit findet, wie das Blatt lag. Die Marke, die Sie gerade eintippen, ist im Bild eingekreist. Lassen Sie eine Zeile leer, wenn eine Marke nicht lesbar ist; eine falsch gemessene Marke findet und nennt der Fit. Mit einem Scanner importieren Sie stattdessen einen Scan: die Marken werden für Sie gefunden und nummeriert. Mit einem Lineal allein messen Sie im zweiten Reiter Abstände zwischen Marken.</translation>
        </message>
        <message>
            <source>Coordinates (x, y)</source>
            <translation>Koordinaten (x, y)</translation>
        </message>
        <message>
            <source>Distances between marks</source>
            <translation>Abstände zwischen Marken</translation>
        </message>
        <message>
            <source>Only %1 distances are measured; measure at least %2, about four for each mark (the fit finds 5 lengths and 2 motor zeros).</source>
            <translation>Nur %1 Abstände sind gemessen; messen Sie mindestens %2, etwa vier je Marke (der Fit bestimmt 5 Längen und 2 Motor-Nullpunkte).</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::calibration::PatternPage</name>
        <message>
            <source>1. Choose the pattern</source>
            <translation>1. Das Muster wählen</translation>
        </message>
        <message>
            <source>Calibration marks</source>
            <translation>Kalibriermarken</translation>
        </message>
        <message>
            <source>Accuracy pattern only (10 lines)</source>
            <translation>Nur Genauigkeitsmuster (10 Linien)</translation>
        </message>
        <message>
            <source> marks</source>
            <translation> Marken</translation>
        </message>
        <message>
            <source>More marks: a more certain fit, more to measure. 25 is a good start.</source>
            <translation>Mehr Marken: eine sicherere Anpassung, mehr zu messen. 25 sind ein guter Anfang.</translation>
        </message>
        <message>
            <source>Marks for the fit:</source>
            <translation>Marken für die Anpassung:</translation>
        </message>
        <message>
            <source>&lt;span style='color:#b00000'&gt;%1&lt;/span&gt;</source>
            <translation>&lt;span style='color:#b00000'&gt;%1&lt;/span&gt;</translation>
        </message>
        <message>
            <source>For &lt;b&gt;%1&lt;/b&gt;: %2 marks for the fit and %3 marks in backlash rows%4.</source>
            <translation>Für &lt;b&gt;%1&lt;/b&gt;: %2 Marken für die Anpassung und %3 Marken in Umkehrspiel-Reihen%4.</translation>
        </message>
        <message>
            <source>, with the accuracy lines in the middle</source>
            <translation>, mit den Genauigkeitslinien in der Mitte</translation>
        </message>
        <message>
            <source>For &lt;b&gt;%1&lt;/b&gt;: ten lines of 40 mm in the middle of the working area.</source>
            <translation>Für &lt;b&gt;%1&lt;/b&gt;: zehn Linien zu 40 mm in der Mitte des Arbeitsbereichs.</translation>
        </message>
        <message>
            <source>No machine is built exactly as drawn: a link cut half a millimetre long or a motor zero set by eye bends every drawing. The studio draws a &lt;b&gt;pattern&lt;/b&gt; of numbered marks, you measure where they really landed, and a fit finds the machine's true link lengths and motor zeros.&lt;br&gt;&lt;br&gt;&lt;b&gt;Calibration marks&lt;/b&gt;: numbered dots in rings spread over the whole working area, plus rows that show the slack (backlash) of each motor. Use these to calibrate.&lt;br&gt;&lt;b&gt;Accuracy pattern&lt;/b&gt; (Hoang): ten parallel lines, 40 mm long and 10 mm apart, to judge straightness and length before and after: you measure each line's length and straightness with a ruler in the wizard's last step.</source>
            <translation>Keine Maschine ist genau so gebaut wie gezeichnet: ein Glied einen halben Millimeter zu lang oder ein Motor-Nullpunkt nach Augenmaß verbiegt jede Zeichnung. Das Studio zeichnet ein &lt;b&gt;Muster&lt;/b&gt; aus nummerierten Marken, Sie messen, wo sie wirklich gelandet sind, und ein Fit findet die wahren Gliederlängen und Motor-Nullpunkte der Maschine.&lt;br&gt;&lt;br&gt;&lt;b&gt;Kalibriermarken&lt;/b&gt;: nummerierte Punkte in Ringen über den ganzen Arbeitsbereich verteilt, dazu Reihen, die das Spiel jedes Motors zeigen. Damit kalibrieren Sie.&lt;br&gt;&lt;b&gt;Genauigkeitsmuster&lt;/b&gt; (Hoang): zehn parallele Linien, 40 mm lang und 10 mm auseinander, um Geradheit und Länge vorher und nachher zu beurteilen: Sie messen Länge und Geradheit jeder Linie mit einem Lineal im letzten Schritt des Assistenten.</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::calibration::SheetLayer</name>
        <message>
            <source>Calibration pattern (plan)</source>
            <translation>Kalibriermuster (Plan)</translation>
        </message>
        <message>
            <source>Drawn by the pen (simulated imperfect machine)</source>
            <translation>Vom Stift gezeichnet (simulierte unvollkommene Maschine)</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::calibration::SimTraceLayer</name>
        <message>
            <source>Drawn by the simulated pen (imperfect machine)</source>
            <translation>Vom simulierten Stift gezeichnet (unvollkommene Maschine)</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::calibration::SimulatedMachineDialog</name>
        <message>
            <source>Simulated machine</source>
            <translation>Simulierte Maschine</translation>
        </message>
        <message>
            <source>The built-in simulated machine can be built &lt;b&gt;imperfectly&lt;/b&gt;, as a real one is: its links a little longer or shorter than the profile says, its motor zeros off, play in its drives. It then draws what such a machine really draws (shown on the canvas beside the plan), so you can try calibration (Machine &amp;gt; Calibrate...) without hardware.&lt;br&gt;&lt;br&gt;The amounts apply at once, also to a simulated machine that is connected, and are kept until you change them here. The status bar says so while the machine is imperfect.</source>
            <translation>Die eingebaute simulierte Maschine kann &lt;b&gt;unvollkommen&lt;/b&gt; gebaut werden, wie eine echte: ihre Glieder etwas länger oder kürzer, als das Profil sagt, ihre Motor-Nullpunkte verschoben, Spiel in den Antrieben. Sie zeichnet dann, was eine solche Maschine wirklich zeichnet (auf der Zeichenfläche neben dem Plan), so können Sie die Kalibrierung (Maschine &amp;gt; Kalibrieren...) ohne Hardware ausprobieren.&lt;br&gt;&lt;br&gt;Die Werte gelten sofort, auch für eine verbundene simulierte Maschine, und bleiben, bis Sie sie hier ändern. Die Statusleiste zeigt es an, solange die Maschine unvollkommen ist.</translation>
        </message>
        <message>
            <source>Perfect machine</source>
            <translation>Perfekte Maschine</translation>
        </message>
        <message>
            <source>All amounts zero: the simulated machine is exactly the profile</source>
            <translation>Alle Werte null: die simulierte Maschine ist genau das Profil</translation>
        </message>
        <message>
            <source>Example</source>
            <translation>Beispiel</translation>
        </message>
        <message>
            <source>A typical home-built machine: links off by up to 0.5 mm, zeros by about 1°, some play</source>
            <translation>Eine typische selbstgebaute Maschine: Glieder bis 0,5 mm daneben, Nullpunkte um etwa 1°, etwas Spiel</translation>
        </message>
        <message>
            <source>Simulated &amp;machine...</source>
            <translation>Simulierte &amp;Maschine...</translation>
        </message>
        <message>
            <source>Build the simulated machine imperfectly, to try calibration without hardware</source>
            <translation>Die simulierte Maschine unvollkommen bauen, um die Kalibrierung ohne Hardware auszuprobieren</translation>
        </message>
        <message>
            <source>OK</source>
            <translation>OK</translation>
        </message>
        <message>
            <source>Cancel</source>
            <translation>Abbrechen</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::calibration::SimulatedTruth</name>
        <message>
            <source>%1 %2 mm</source>
            <translation>%1 %2 mm</translation>
        </message>
        <message>
            <source>motor %1 zero %2°</source>
            <translation>Motor %1 Nullpunkt %2°</translation>
        </message>
        <message>
            <source>motor %1 backlash %2°</source>
            <translation>Motor %1 Spiel %2°</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::calibration::SimulatedTruthBadge</name>
        <message>
            <source>Simulated machine: imperfect</source>
            <translation>Simulierte Maschine: unvollkommen</translation>
        </message>
        <message>
            <source>The built-in simulated machine differs from the profile: %1. Click to change it (Machine &gt; Simulated machine...).</source>
            <translation>Die eingebaute simulierte Maschine weicht vom Profil ab: %1. Klicken, um das zu ändern (Maschine &gt; Simulierte Maschine...).</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::calibration::TrueMachineForm</name>
        <message>
            <source>How much longer the real part is than the profile says (negative: shorter).</source>
            <translation>Um wie viel das echte Teil länger ist, als das Profil sagt (negativ: kürzer).</translation>
        </message>
        <message>
            <source>a1 longer by</source>
            <translation>a1 länger um</translation>
        </message>
        <message>
            <source> mm</source>
            <translation> mm</translation>
        </message>
        <message>
            <source>b1 longer by</source>
            <translation>b1 länger um</translation>
        </message>
        <message>
            <source>a2 longer by</source>
            <translation>a2 länger um</translation>
        </message>
        <message>
            <source>b2 longer by</source>
            <translation>b2 länger um</translation>
        </message>
        <message>
            <source>motors farther apart by</source>
            <translation>Motorabstand größer um</translation>
        </message>
        <message>
            <source>How much farther apart the real motor axes are.</source>
            <translation>Um wie viel die echten Motorachsen weiter auseinander liegen.</translation>
        </message>
        <message>
            <source>motor 1 zero off by</source>
            <translation>Nullpunkt Motor 1 versetzt um</translation>
        </message>
        <message>
            <source> °</source>
            <translation> °</translation>
        </message>
        <message>
            <source>The real arm angle is the commanded one plus this.</source>
            <translation>Der echte Armwinkel ist der befohlene plus dieser Wert.</translation>
        </message>
        <message>
            <source>motor 2 zero off by</source>
            <translation>Nullpunkt Motor 2 versetzt um</translation>
        </message>
        <message>
            <source>motor 1 backlash</source>
            <translation>Umkehrspiel Motor 1</translation>
        </message>
        <message>
            <source>Play in the drive: the arm lags this much when the motor reverses.</source>
            <translation>Spiel im Antrieb: der Arm bleibt so weit zurück, wenn der Motor die Richtung wechselt.</translation>
        </message>
        <message>
            <source>motor 2 backlash</source>
            <translation>Umkehrspiel Motor 2</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::calibration::VerifyPage</name>
        <message>
            <source>6. Draw the verification pattern</source>
            <translation>6. Das Prüfmuster zeichnen</translation>
        </message>
        <message>
            <source>Draw on the connected machine</source>
            <translation>Auf der verbundenen Maschine zeichnen</translation>
        </message>
        <message>
            <source>Export G-code...</source>
            <translation>G-Code exportieren...</translation>
        </message>
        <message>
            <source>The verification pattern is drawn.</source>
            <translation>Das Prüfmuster ist gezeichnet.</translation>
        </message>
        <message>
            <source>Drawing the verification pattern...</source>
            <translation>Das Prüfmuster wird gezeichnet...</translation>
        </message>
        <message>
            <source>Export the verification G-code</source>
            <translation>Den G-Code des Prüfmusters exportieren</translation>
        </message>
        <message>
            <source>G-code (*.gcode *.nc)</source>
            <translation>G-Code (*.gcode *.nc)</translation>
        </message>
        <message>
            <source>Wrote %1.</source>
            <translation>%1 geschrieben.</translation>
        </message>
        <message>
            <source>Cannot write %1.</source>
            <translation>%1 kann nicht geschrieben werden.</translation>
        </message>
        <message>
            <source>&lt;b&gt;Simulation:&lt;/b&gt; the imperfect machine puts the marks %1 mm RMS (largest %2 mm) from where they are meant with the old profile, and &lt;b&gt;%3 mm RMS (largest %4 mm)&lt;/b&gt; with the profile now in use%5.</source>
            <translation>&lt;b&gt;Simulation:&lt;/b&gt; Die unvollkommene Maschine setzt die Marken mit dem alten Profil %1 mm RMS (größter %2 mm) neben ihren Sollort, und &lt;b&gt;%3 mm RMS (größter %4 mm)&lt;/b&gt; mit dem jetzt verwendeten Profil%5.</translation>
        </message>
        <message>
            <source> (the calibration is not applied)</source>
            <translation> (die Kalibrierung ist nicht übernommen)</translation>
        </message>
        <message>
            <source>Draw the pattern once more, now planned with the calibrated profile, on a fresh sheet. Its marks should land where they were meant, and the accuracy lines should be straight and 40 mm long: &lt;b&gt;Next&lt;/b&gt; measures the lines with a ruler for a before/after figure.</source>
            <translation>Zeichnen Sie das Muster noch einmal, nun mit dem kalibrierten Profil geplant, auf ein neues Blatt. Seine Marken sollten dort landen, wo sie gemeint sind, und die Genauigkeitslinien sollten gerade und 40 mm lang sein: &lt;b&gt;Weiter&lt;/b&gt; misst die Linien mit einem Lineal für einen Vorher-nachher-Wert.</translation>
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
            <source>Save a picture of the window once the job is planned, then quit.</source>
            <translation>Ein Bild des Fensters speichern, sobald der Auftrag geplant ist, dann beenden.</translation>
        </message>
        <message>
            <source>With --screenshot: show the workspace legend (legend) or a map (transmission, conditioning or resolution).</source>
            <translation>Mit --screenshot: die Arbeitsraum-Legende (legend) oder eine Karte (transmission, conditioning oder resolution) zeigen.</translation>
        </message>
        <message>
            <source>With --screenshot: simulation position as a fraction of the job (0 to 1).</source>
            <translation>Mit --screenshot: Position der Simulation als Anteil des Auftrags (0 bis 1).</translation>
        </message>
        <message>
            <source>Print how long opening and planning the drawing took, stage by stage, to stderr (as fivebar plan --timings).</source>
            <translation>Ausgeben, wie lange das Öffnen und Planen der Zeichnung gedauert hat, Schritt für Schritt, auf stderr (wie fivebar plan --timings).</translation>
        </message>
        <message>
            <source>Machine profile: a preset name or a profile JSON file (default: the last one used, else maker-plotter).</source>
            <translation>Maschinenprofil: ein Vorgabename oder eine Profil-JSON-Datei (Standard: das zuletzt verwendete, sonst maker-plotter).</translation>
        </message>
        <message>
            <source>Plan the drawing or project as the studio does, write the G-code and exit (no window).</source>
            <translation>Die Zeichnung oder das Projekt wie im Studio planen, den G-Code schreiben und beenden (ohne Fenster).</translation>
        </message>
        <message>
            <source>SVG drawing or project to open.</source>
            <translation>SVG-Zeichnung oder Projekt zum Öffnen.</translation>
        </message>
        <message>
            <source>Filled shapes: outline (default), hatch or none; with hatch: SPACING_MM and ANGLE_DEG after colons.</source>
            <translation>Gefüllte Formen: outline (Standard), hatch oder none; bei hatch: SPACING_MM und ANGLE_DEG nach Doppelpunkten.</translation>
        </message>
        <message>
            <source>User interface language: de, en, es or fr (default: View &gt; Language, else the system's).</source>
            <translation>Sprache der Oberfläche: de, en, es oder fr (Vorgabe: Ansicht &gt; Sprache, sonst die des Systems).</translation>
        </message>
        <message>
            <source>Connect to the board on this port at start, as the Connect button does: a serial device, a pseudo-terminal or tcp:HOST:PORT.</source>
            <translation>Beim Start mit der Steuerung an diesem Anschluss verbinden, wie es die Schaltfläche Verbinden tut: ein serielles Gerät, ein Pseudoterminal oder tcp:HOST:PORT.</translation>
        </message>
        <message>
            <source>With --port: the baud rate (default: the machine profile's, usually 115200).</source>
            <translation>Mit --port: die Baudrate (Standard: die des Maschinenprofils, meist 115200).</translation>
        </message>
    </context>
    <context>
        <name>Profile</name>
        <message>
            <source>deg</source>
            <translation>°</translation>
        </message>
        <message>
            <source>%1 must be a finite number of millimetres</source>
            <translation>%1 muss eine endliche Zahl in Millimetern sein</translation>
        </message>
        <message>
            <source>%1 is %2 mm; it must be zero or positive</source>
            <translation>%1 ist %2 mm; der Wert muss null oder positiv sein</translation>
        </message>
        <message>
            <source>%1 is %2 mm; it must be positive</source>
            <translation>%1 ist %2 mm; der Wert muss positiv sein</translation>
        </message>
        <message>
            <source>the legs can never meet: a1+b1 + a2+b2 = %1 mm is less than w = %2 mm</source>
            <translation>die Arme können sich nie treffen: a1+b1 + a2+b2 = %1 mm ist kleiner als w = %2 mm</translation>
        </message>
        <message>
            <source>the legs can never meet: one leg's dead zone |a-b| encloses the other leg's whole reach</source>
            <translation>die Arme können sich nie treffen: der tote Bereich |a-b| eines Arms umschließt die ganze Reichweite des anderen</translation>
        </message>
        <message>
            <source>%1 limits must be finite numbers of degrees</source>
            <translation>die Grenzen von %1 müssen endliche Gradzahlen sein</translation>
        </message>
        <message>
            <source>%1 minimum %2 deg is not below its maximum %3 deg, so no pose is allowed</source>
            <translation>das Minimum von %1 (%2°) liegt nicht unter dem Maximum (%3°), also ist keine Stellung erlaubt</translation>
        </message>
        <message>
            <source>the joint limits exclude every pose in which the linkage closes</source>
            <translation>die Gelenkgrenzen schließen jede Stellung aus, in der sich das Gestänge schließt</translation>
        </message>
        <message>
            <source>calibration.version %1 is not supported; this program reads version %2</source>
            <translation>calibration.version %1 wird nicht unterstützt; dieses Programm liest Version %2</translation>
        </message>
        <message>
            <source>calibration.date must be an ISO 8601 date like 2026-12-01 or 2026-12-01T22:30:00Z, got "%1"</source>
            <translation>calibration.date muss ein Datum nach ISO 8601 sein, etwa 2026-12-01 oder 2026-12-01T22:30:00Z, ist aber "%1"</translation>
        </message>
        <message>
            <source>calibration.outliers[%1] must be a mark id, got an empty string</source>
            <translation>calibration.outliers[%1] muss eine Marken-ID sein, ist aber leer</translation>
        </message>
        <message>
            <source>%1 must be a finite number</source>
            <translation>%1 muss eine endliche Zahl sein</translation>
        </message>
        <message>
            <source>%1 (%2) must be below %3 (%4)</source>
            <translation>%1 (%2) muss kleiner als %3 (%4) sein</translation>
        </message>
        <message>
            <source>tool.zUpMm (%1) must be above tool.zDownMm (%2)</source>
            <translation>tool.zUpMm (%1) muss größer als tool.zDownMm (%2) sein</translation>
        </message>
        <message>
            <source>%1 (%2) lies outside the joint limits [%3, %4]</source>
            <translation>%1 (%2) liegt außerhalb der Gelenkgrenzen [%3; %4]</translation>
        </message>
        <message>
            <source>name must not be empty</source>
            <translation>name darf nicht leer sein</translation>
        </message>
        <message>
            <source>workingMode must be one of ++, +-, -+, --, got "%1"</source>
            <translation>workingMode muss ++, +-, -+ oder -- sein, ist aber "%1"</translation>
        </message>
        <message>
            <source>assemblyMode must be + or -, got "%1"</source>
            <translation>assemblyMode muss + oder - sein, ist aber "%1"</translation>
        </message>
        <message>
            <source>tool.kind must be pen-servo, z-axis or laser, got "%1"</source>
            <translation>tool.kind muss pen-servo, z-axis oder laser sein, ist aber "%1"</translation>
        </message>
        <message>
            <source>schema must be "%1", got "%2" (is this a machine profile?)</source>
            <translation>schema muss "%1" sein, ist aber "%2" (ist das ein Maschinenprofil?)</translation>
        </message>
        <message>
            <source>version %1 is not supported; this program reads version %2</source>
            <translation>Version %1 wird nicht unterstützt; dieses Programm liest Version %2</translation>
        </message>
        <message>
            <source>%1:%2:%3: invalid JSON: %4</source>
            <translation>%1:%2:%3: ungültiges JSON: %4</translation>
        </message>
        <message>
            <source>the profile must be a JSON object ({...})</source>
            <translation>das Profil muss ein JSON-Objekt sein ({...})</translation>
        </message>
        <message>
            <source>%1 must be positive, got %2</source>
            <translation>%1 muss positiv sein, ist aber %2</translation>
        </message>
        <message>
            <source>%1 must be zero or positive, got %2</source>
            <translation>%1 muss null oder positiv sein, ist aber %2</translation>
        </message>
        <message>
            <source>%1 must be between %2 and %3 %4, got %5</source>
            <translation>%1 muss zwischen %2 und %3 %4 liegen, ist aber %5</translation>
        </message>
        <message>
            <source>%1 must be between %2 and %3, got %4</source>
            <translation>%1 muss zwischen %2 und %3 liegen, ist aber %4</translation>
        </message>
        <message>
            <source>cannot open %1: %2</source>
            <translation>%1 kann nicht geöffnet werden: %2</translation>
        </message>
        <message>
            <source>unknown machine preset '%1' (presets: %2; or give a profile file path)</source>
            <translation>unbekannte Maschinenvorlage '%1' (Vorlagen: %2; oder den Pfad einer Profildatei angeben)</translation>
        </message>
        <message>
            <source>a number</source>
            <translation>eine Zahl</translation>
        </message>
        <message>
            <source>a string</source>
            <translation>ein Text</translation>
        </message>
        <message>
            <source>a boolean</source>
            <translation>ein Wahrheitswert</translation>
        </message>
        <message>
            <source>an object</source>
            <translation>ein Objekt</translation>
        </message>
        <message>
            <source>an array</source>
            <translation>eine Liste</translation>
        </message>
        <message>
            <source>null</source>
            <translation>null</translation>
        </message>
        <message>
            <source>an unsupported value</source>
            <translation>ein nicht unterstützter Wert</translation>
        </message>
        <message>
            <source>%1 is missing (it is required)</source>
            <translation>%1 fehlt (das Feld ist Pflicht)</translation>
        </message>
        <message>
            <source>%1 must be %2, got %3 "%4"</source>
            <translation>%1 muss %2 sein, ist aber %3 "%4"</translation>
        </message>
        <message>
            <source>%1 must be %2, got %3</source>
            <translation>%1 muss %2 sein, ist aber %3</translation>
        </message>
        <message>
            <source>an integer</source>
            <translation>eine ganze Zahl</translation>
        </message>
        <message>
            <source>%1 is out of the integer range</source>
            <translation>%1 liegt außerhalb des Ganzzahlbereichs</translation>
        </message>
        <message>
            <source>true or false</source>
            <translation>true oder false</translation>
        </message>
        <message>
            <source>an array of strings</source>
            <translation>eine Liste von Texten</translation>
        </message>
        <message>
            <source>%1 must be a string, got %2</source>
            <translation>%1 muss ein Text sein, ist aber %2</translation>
        </message>
        <message>
            <source>%1 is not a known field (expected one of: %2)</source>
            <translation>%1 ist kein bekanntes Feld (erwartet: eines von %2)</translation>
        </message>
        <message>
            <source>machine: %1</source>
            <translation>Maschine: %1</translation>
        </message>
    </context>
    <context>
        <name>CalibrationFile</name>
        <message>
            <source>%1: header must be '%2'</source>
            <translation>%1: die Kopfzeile muss „%2“ lauten</translation>
        </message>
        <message>
            <source>%1: %2 fields, expected %3</source>
            <translation>%1: %2 Felder, erwartet %3</translation>
        </message>
        <message>
            <source>%1: empty file (expected the header '%2')</source>
            <translation>%1: leere Datei (erwartet wird die Kopfzeile „%2“)</translation>
        </message>
        <message>
            <source>%1: %2: '%3' is not a number</source>
            <translation>%1: %2: „%3“ ist keine Zahl</translation>
        </message>
        <message>
            <source>%1: cannot open the file</source>
            <translation>%1: die Datei lässt sich nicht öffnen</translation>
        </message>
        <message>
            <source>%1: id: '%2' is not a positive integer</source>
            <translation>%1: id: „%2“ ist keine positive ganze Zahl</translation>
        </message>
        <message>
            <source>%1: id: duplicate id %2</source>
            <translation>%1: id: doppelte ID %2</translation>
        </message>
        <message>
            <source>%1: kind: '%2' is not grid or backlash</source>
            <translation>%1: kind: „%2“ ist weder grid noch backlash</translation>
        </message>
        <message>
            <source>%1: %2: '%3' is not + or -</source>
            <translation>%1: %2: „%3“ ist weder + noch -</translation>
        </message>
        <message>
            <source>%1: group: '%2' is not a non-negative integer</source>
            <translation>%1: group: „%2“ ist keine nicht negative ganze Zahl</translation>
        </message>
        <message>
            <source>%1: motor: '%2' is not 0, 1 or 2</source>
            <translation>%1: motor: „%2“ ist nicht 0, 1 oder 2</translation>
        </message>
        <message>
            <source>%1: a backlash mark needs a group and a motor, a grid mark neither</source>
            <translation>%1: eine Spielmarke braucht eine Gruppe und einen Motor, eine Rastermarke keins von beiden</translation>
        </message>
        <message>
            <source>%1: ring_radius_mm: '%2' is not a positive number</source>
            <translation>%1: ring_radius_mm: „%2“ ist keine positive Zahl</translation>
        </message>
        <message>
            <source>%1: no marks</source>
            <translation>%1: keine Marken</translation>
        </message>
        <message>
            <source>%1: backlash row %2 has %3 marks, expected 3</source>
            <translation>%1: Spielreihe %2 hat %3 Marken, erwartet 3</translation>
        </message>
        <message>
            <source>%1: the file is empty (expected a header line: %2)</source>
            <translation>%1: die Datei ist leer (erwartet wird eine Kopfzeile: %2)</translation>
        </message>
        <message>
            <source>%1: the header has no column %2 (expected %3)</source>
            <translation>%1: der Kopfzeile fehlt die Spalte %2 (erwartet %3)</translation>
        </message>
        <message>
            <source>%1: missing field %2</source>
            <translation>%1: Feld %2 fehlt</translation>
        </message>
        <message>
            <source>%1: %2 is not a number: "%3"</source>
            <translation>%1: %2 ist keine Zahl: „%3“</translation>
        </message>
        <message>
            <source>%1: duplicate mark id %2 (first on line %3)</source>
            <translation>%1: doppelte Marken-ID %2 (zuerst in Zeile %3)</translation>
        </message>
        <message>
            <source>%1: a distance from mark %2 to itself</source>
            <translation>%1: ein Abstand von Marke %2 zu sich selbst</translation>
        </message>
        <message>
            <source>%1: distance_mm must be positive</source>
            <translation>%1: distance_mm muss positiv sein</translation>
        </message>
        <message>
            <source>%1: duplicate distance %2-%3 (first on line %4)</source>
            <translation>%1: doppelter Abstand %2-%3 (zuerst in Zeile %4)</translation>
        </message>
        <message>
            <source>cannot open %1: %2</source>
            <translation>%1 lässt sich nicht öffnen: %2</translation>
        </message>
    </context>
    <context>
        <name>CalibrationFit</name>
        <message>
            <source>the measurements do not depend on %1 at all</source>
            <translation>die Messungen hängen überhaupt nicht von %1 ab</translation>
        </message>
        <message>
            <source>the fit is ill-conditioned (condition number %1 &gt; %2): the marks cannot separate %3; spread the marks over the whole working area</source>
            <translation>die Anpassung ist schlecht konditioniert (Konditionszahl %1 &gt; %2): die Marken können %3 nicht unterscheiden; verteilen Sie die Marken über den ganzen Arbeitsbereich</translation>
        </message>
        <message>
            <source>%1 distances are too few for %2 parameters: at least %3 distances are needed</source>
            <translation>%1 Abstände sind zu wenige für %2 Parameter: mindestens %3 Abstände sind nötig</translation>
        </message>
        <message>
            <source>%1 marks are too few for %2 parameters: at least %3 marks are needed</source>
            <translation>%1 Marken sind zu wenige für %2 Parameter: mindestens %3 Marken sind nötig</translation>
        </message>
        <message>
            <source>a mark's commanded angles do not close the nominal machine's loop</source>
            <translation>die befohlenen Winkel einer Marke schließen die Kette der Nennmaschine nicht</translation>
        </message>
        <message>
            <source>the fit did not converge within %1 evaluations (are the commanded angles and measurements of the same marks?)</source>
            <translation>die Anpassung ist nach %1 Auswertungen nicht konvergiert (gehören die befohlenen Winkel und die Messungen zu denselben Marken?)</translation>
        </message>
        <message>
            <source>the final fit did not converge within %1 evaluations</source>
            <translation>die abschließende Anpassung ist nach %1 Auswertungen nicht konvergiert</translation>
        </message>
        <message>
            <source>line %1: mark %2 is not in the marks file</source>
            <translation>Zeile %1: Marke %2 steht nicht in der Markendatei</translation>
        </message>
        <message>
            <source>only %1 grid marks measured: at least 3 are needed to place the sheet</source>
            <translation>nur %1 Rastermarken gemessen: mindestens 3 sind nötig, um das Blatt zu platzieren</translation>
        </message>
        <message>
            <source>the measured grid marks all lie on one point</source>
            <translation>die gemessenen Rastermarken liegen alle auf einem Punkt</translation>
        </message>
        <message>
            <source>no backlash row has all three marks measured</source>
            <translation>keine Spielreihe hat alle drei Marken gemessen</translation>
        </message>
    </context>
    <context>
        <name>CalibrationPattern</name>
        <message>
            <source>pattern options out of range</source>
            <translation>Musteroptionen außerhalb des zulässigen Bereichs</translation>
        </message>
        <message>
            <source>no point of the working area (mode %1) has room for a mark</source>
            <translation>kein Punkt des Arbeitsbereichs (Modus %1) hat Platz für eine Marke</translation>
        </message>
        <message>
            <source>only %1 marks fit %2 mm apart in the working area; at least %3 are needed</source>
            <translation>nur %1 Marken passen im Abstand von %2 mm in den Arbeitsbereich; mindestens %3 sind nötig</translation>
        </message>
        <message>
            <source>no drawing order keeps every move between marks under half a turn of a motor</source>
            <translation>keine Zeichenreihenfolge hält jede Bewegung zwischen Marken unter einer halben Motorumdrehung</translation>
        </message>
        <message>
            <source>approach of mark %1</source>
            <translation>Anfahrt von Marke %1</translation>
        </message>
        <message>
            <source>%1: %2</source>
            <translation>%1: %2</translation>
        </message>
    </context>
    <context>
        <name>CalibrationScan</name>
        <message>
            <source>the pattern has fewer than 3 marks</source>
            <translation>das Muster hat weniger als 3 Marken</translation>
        </message>
        <message>
            <source>found %1 marks, the pattern has %2</source>
            <translation>%1 Marken gefunden, das Muster hat %2</translation>
        </message>
        <message>
            <source>no two found marks are as far apart as the pattern's marks (is the dpi right?)</source>
            <translation>keine zwei gefundenen Marken liegen so weit auseinander wie die Marken des Musters (stimmt die Auflösung?)</translation>
        </message>
        <message>
            <source>only %1 of the pattern's %2 marks match the found ones (%3 found): not this pattern, or the dpi is wrong</source>
            <translation>nur %1 der %2 Marken des Musters passen zu den gefundenen (%3 gefunden): nicht dieses Muster, oder die Auflösung ist falsch</translation>
        </message>
        <message>
            <source>ambiguous: two placements of the sheet match %1 and %2 marks</source>
            <translation>mehrdeutig: zwei Lagen des Blatts passen zu %1 und %2 Marken</translation>
        </message>
        <message>
            <source>%1: %2</source>
            <translation>%1: %2</translation>
        </message>
        <message>
            <source>the dpi must be a positive number</source>
            <translation>die Auflösung (dpi) muss eine positive Zahl sein</translation>
        </message>
        <message>
            <source>the image is empty</source>
            <translation>das Bild ist leer</translation>
        </message>
        <message>
            <source>the pattern has no marks</source>
            <translation>das Muster hat keine Marken</translation>
        </message>
        <message>
            <source>no ink found (the image has almost no contrast)</source>
            <translation>keine Tinte gefunden (das Bild hat kaum Kontrast)</translation>
        </message>
        <message>
            <source>no marks found at %1 dpi: the pattern's rings are %2 mm across (%3 px); the ring-like shapes in the image are about %4 px: is it scanned at about %5 dpi?</source>
            <translation>keine Marken bei %1 dpi gefunden: die Ringe des Musters haben %2 mm Durchmesser (%3 px); die ringartigen Formen im Bild sind etwa %4 px groß: wurde mit etwa %5 dpi gescannt?</translation>
        </message>
        <message>
            <source>no marks found at %1 dpi: the pattern's rings are %2 mm across (%3 px)</source>
            <translation>keine Marken bei %1 dpi gefunden: die Ringe des Musters haben %2 mm Durchmesser (%3 px)</translation>
        </message>
        <message>
            <source>cannot read the image (%1)</source>
            <translation>das Bild kann nicht gelesen werden (%1)</translation>
        </message>
        <message>
            <source>found %1 parallel lines of about %2 mm at %3 dpi, expected %4 (is the dpi right, and the whole pattern on the scan?)</source>
            <translation>%1 parallele Linien von etwa %2 mm bei %3 dpi gefunden, erwartet %4 (stimmt die Auflösung, und ist das ganze Muster auf dem Scan?)</translation>
        </message>
        <message>
            <source>the line near (%1, %2) mm has no clear ends</source>
            <translation>die Linie bei (%1, %2) mm hat keine klaren Enden</translation>
        </message>
    </context>
    <context>
        <name>Jog</name>
        <message>
            <source>the machine position is not known yet</source>
            <translation>die Position der Maschine ist noch nicht bekannt</translation>
        </message>
        <message>
            <source>the current motor angles do not close the linkage</source>
            <translation>die aktuellen Motorwinkel schließen das Gestänge nicht</translation>
        </message>
        <message>
            <source>the line leaves the workspace</source>
            <translation>die Linie verlässt den Arbeitsbereich</translation>
        </message>
        <message>
            <source>the arms cannot follow the straight line closely enough</source>
            <translation>die Arme können der geraden Linie nicht genau genug folgen</translation>
        </message>
        <message>
            <source>stopped after %1 mm: %2</source>
            <translation>nach %1 mm angehalten: %2</translation>
        </message>
        <message>
            <source>no jog direction</source>
            <translation>keine Verfahrrichtung</translation>
        </message>
        <message>
            <source>no safe travel to that point</source>
            <translation>kein sicherer Weg zu diesem Punkt</translation>
        </message>
        <message>
            <source>the point is out of reach</source>
            <translation>der Punkt ist außer Reichweite</translation>
        </message>
        <message>
            <source>the job has no pen-down strokes to frame</source>
            <translation>der Auftrag hat keine Striche mit abgesenktem Stift, die umrahmt werden könnten</translation>
        </message>
        <message>
            <source>cannot reach the frame's first corner: %1</source>
            <translation>die erste Ecke des Rahmens ist nicht erreichbar: %1</translation>
        </message>
        <message>
            <source>frame edge %1: %2</source>
            <translation>Rahmenkante %1: %2</translation>
        </message>
    </context>
    <context>
        <name>MotionCheck</name>
        <message>
            <source>G2/G3 arcs are not arcs in joint space (X and Y are motor angles): plan the drawing with 'fivebar plan', which turns arcs into checked straight segments</source>
            <translation>G2/G3-Bögen sind im Gelenkraum keine Bögen (X und Y sind Motorwinkel): planen Sie die Zeichnung mit 'fivebar plan', das Bögen in geprüfte gerade Segmente umwandelt</translation>
        </message>
        <message>
            <source>probing (G38) is not supported on a five-bar machine</source>
            <translation>Antasten (G38) wird auf einer Fünfgelenkmaschine nicht unterstützt</translation>
        </message>
        <message>
            <source>G20 (inches) would scale the motor angles by 25.4: X and Y are degrees, use G21</source>
            <translation>G20 (Zoll) würde die Motorwinkel mit 25,4 skalieren: X und Y sind Grad, verwenden Sie G21</translation>
        </message>
        <message>
            <source>G10/G92 change the coordinates the checks rely on: %1</source>
            <translation>G10/G92 ändern die Koordinaten, auf denen die Prüfungen beruhen: %1</translation>
        </message>
        <message>
            <source>G55-G59 select another work coordinate system; the checked link works in G54</source>
            <translation>G55-G59 wählen ein anderes Werkstückkoordinatensystem; die geprüfte Verbindung arbeitet in G54</translation>
        </message>
        <message>
            <source>a jog ($J=) takes only G90, G91, G53 and G21</source>
            <translation>ein Verfahrbefehl ($J=) akzeptiert nur G90, G91, G53 und G21</translation>
        </message>
        <message>
            <source>the board would refuse the jog (error:15)</source>
            <translation>die Steuerung würde das Verfahren ablehnen (error:15)</translation>
        </message>
        <message>
            <source>the board would stop with a soft-limit alarm (ALARM:2)</source>
            <translation>die Steuerung würde mit einem Software-Endlagen-Alarm anhalten (ALARM:2)</translation>
        </message>
        <message>
            <source>the target %1 takes motor %2 to %3 deg in machine coordinates, outside the board's soft-limit travel %4..0 deg ($%5=%6): %7; home the machine or set its reference so that the travel matches the profile, or choose a target inside it</source>
            <translation>das Ziel %1 bringt Motor %2 auf %3 Grad in Maschinenkoordinaten, außerhalb des Software-Verfahrwegs der Steuerung %4..0 Grad ($%5=%6): %7; referenzieren Sie die Maschine oder setzen Sie ihre Referenz so, dass der Verfahrweg zum Profil passt, oder wählen Sie ein Ziel darin</translation>
        </message>
        <message>
            <source>set the machine's reference with 'fivebar reference' (or home it with 'fivebar home')</source>
            <translation>setzen Sie die Referenz der Maschine mit 'fivebar reference' (oder referenzfahren Sie sie mit 'fivebar home')</translation>
        </message>
        <message>
            <source>choose a target inside the workspace (fivebar workspace shows it)</source>
            <translation>wählen Sie ein Ziel innerhalb des Arbeitsbereichs ('fivebar workspace' zeigt ihn)</translation>
        </message>
        <message>
            <source>(%1, %2) deg</source>
            <translation>(%1, %2) Grad</translation>
        </message>
        <message>
            <source>G28/G30 go to a position stored on the board, which is not known here; move to the point with a G0 line instead</source>
            <translation>G28/G30 fahren zu einer auf der Steuerung gespeicherten Position, die hier nicht bekannt ist; fahren Sie den Punkt stattdessen mit einer G0-Zeile an</translation>
        </message>
        <message>
            <source>the machine's position %1 is not a safe pose of %2 (%3), so no move from it can be checked: %4 first</source>
            <translation>die Position der Maschine %1 ist keine sichere Stellung von %2 (%3), daher kann keine Bewegung von ihr aus geprüft werden: %4 zuerst</translation>
        </message>
        <message>
            <source>the move from %1 to %2 %3; %4</source>
            <translation>die Bewegung von %1 nach %2 %3; %4</translation>
        </message>
    </context>
    <context>
        <name>SoftLimits</name>
        <message>
            <source>line %1 moves motor %2 to %3 deg in machine coordinates, outside the board's soft-limit travel %4..0 ($%5=%6)</source>
            <translation>Zeile %1 bringt Motor %2 auf %3 Grad in Maschinenkoordinaten, außerhalb des Software-Verfahrwegs der Steuerung %4..0 ($%5=%6)</translation>
        </message>
    </context>
    <context>
        <name>fivebar::session::BoardPreflight</name>
        <message>
            <source>The board's soft limits would stop this job with an alarm (ALARM:2): %1. The board checks its travel ($130, $131) in machine coordinates, which the reference pose shifted against the drawing's. Home the machine, or make the board's settings match the profile (Machine settings...), then start again.</source>
            <translation>Die Software-Endlagen der Steuerung würden diesen Auftrag mit einem Alarm anhalten (ALARM:2): %1. Die Steuerung prüft ihren Verfahrweg ($130, $131) in Maschinenkoordinaten, die die Referenzstellung gegenüber denen der Zeichnung verschoben hat. Referenzfahren Sie die Maschine oder gleichen Sie die Einstellungen der Steuerung an das Profil an (Maschineneinstellungen...) und starten Sie dann erneut.</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::MachineLayer</name>
        <message>
            <source>Position unknown: set the reference pose</source>
            <translation>Position unbekannt: Referenzpose setzen</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::PortBox</name>
        <message>
            <source>/dev/ttyUSB0 or tcp:HOST:PORT</source>
            <translation>/dev/ttyUSB0 oder tcp:HOST:PORT</translation>
        </message>
        <message>
            <source>The board's port: pick one, or type any name: a serial device, a /dev/serial/by-id link, a pseudo-terminal (e.g. the firmware simulator's) or a network port tcp:HOST:PORT (ser2net, a FluidNC or grblHAL board)</source>
            <translation>Der Anschluss der Steuerung: einen auswählen oder einen beliebigen Namen eingeben: ein serielles Gerät, einen Link unter /dev/serial/by-id, ein Pseudoterminal (z. B. das des Firmware-Simulators) oder einen Netzwerkanschluss tcp:HOST:PORT (ser2net, eine FluidNC- oder grblHAL-Steuerung)</translation>
        </message>
        <message>
            <source>Simulated machine (built in)</source>
            <translation>Simulierte Maschine (eingebaut)</translation>
        </message>
        <message>
            <source>Connected to recently</source>
            <translation>Kürzlich verbunden</translation>
        </message>
        <message>
            <source>Choose a port or type its name, for example /dev/ttyUSB0, a pseudo-terminal such as /tmp/grblpty, or a network port tcp:HOST:PORT.</source>
            <translation>Wählen Sie einen Anschluss oder geben Sie seinen Namen ein, zum Beispiel /dev/ttyUSB0, ein Pseudoterminal wie /tmp/grblpty oder einen Netzwerkanschluss tcp:HOST:PORT.</translation>
        </message>
        <message>
            <source>%1 is not a network port: write it as tcp:HOST:PORT, for example tcp:192.168.1.20:23.</source>
            <translation>%1 ist kein Netzwerkanschluss: Schreiben Sie ihn als tcp:HOST:PORT, zum Beispiel tcp:192.168.1.20:23.</translation>
        </message>
        <message>
            <source>There is no port %1. Check the name, that the board is plugged in and powered, or that the simulator is running (Refresh lists the serial ports found).</source>
            <translation>Es gibt keinen Anschluss %1. Prüfen Sie den Namen, ob die Steuerung eingesteckt und eingeschaltet ist oder ob der Simulator läuft (Aktualisieren listet die gefundenen seriellen Schnittstellen auf).</translation>
        </message>
        <message>
            <source>%1 is a folder, not a port: choose the board's serial port (e.g. /dev/ttyUSB0) or type a network port tcp:HOST:PORT.</source>
            <translation>%1 ist ein Ordner, kein Anschluss: Wählen Sie die serielle Schnittstelle der Steuerung (z. B. /dev/ttyUSB0) oder geben Sie einen Netzwerkanschluss tcp:HOST:PORT ein.</translation>
        </message>
        <message>
            <source>%1 is a file, not a port: choose the board's serial port (e.g. /dev/ttyUSB0) or type a network port tcp:HOST:PORT.</source>
            <translation>%1 ist eine Datei, kein Anschluss: Wählen Sie die serielle Schnittstelle der Steuerung (z. B. /dev/ttyUSB0) oder geben Sie einen Netzwerkanschluss tcp:HOST:PORT ein.</translation>
        </message>
        <message>
            <source>No permission to use %1: add your user to the group that owns it (usually dialout: sudo adduser $USER dialout), then log out and in again.</source>
            <translation>Keine Berechtigung für %1: Fügen Sie Ihren Benutzer der Gruppe hinzu, der der Anschluss gehört (meist dialout: sudo adduser $USER dialout), und melden Sie sich danach ab und wieder an.</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::RecoveryBar</name>
        <message>
            <source>Reset</source>
            <translation>Zurücksetzen</translation>
        </message>
        <message>
            <source>Soft reset (Ctrl-X): stops everything; the machine keeps its position unless it was moving.</source>
            <translation>Soft-Reset (Strg-X): hält alles an; die Maschine behält ihre Position, sofern sie sich nicht bewegt hat.</translation>
        </message>
        <message>
            <source>Unlock ($X)</source>
            <translation>Entsperren ($X)</translation>
        </message>
        <message>
            <source>Leave the alarm state without homing. Only when you know the machine stands where the studio shows it.</source>
            <translation>Den Alarmzustand ohne Referenzfahrt verlassen. Nur wenn Sie wissen, dass die Maschine dort steht, wo das Studio sie zeigt.</translation>
        </message>
        <message>
            <source>Alarm %1</source>
            <translation>Alarm %1</translation>
        </message>
        <message>
            <source>Home ($H)</source>
            <translation>Referenzfahrt ($H)</translation>
        </message>
        <message>
            <source>Set reference pose</source>
            <translation>Referenzpose setzen</translation>
        </message>
        <message>
            <source>Run the homing cycle; the machine moves to its switches.</source>
            <translation>Referenzfahrt ausführen; die Maschine fährt an ihre Endschalter.</translation>
        </message>
        <message>
            <source>Declare that the machine now stands at the profile's home pose (G10 L20).</source>
            <translation>Festlegen, dass die Maschine jetzt in der Ausgangspose des Profils steht (G10 L20).</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::AlarmStrip</name>
        <message>
            <source>Alarm %1: the machine stopped.</source>
            <translation>Alarm %1: Die Maschine hat angehalten.</translation>
        </message>
        <message>
            <source>Alarm: the machine is locked.</source>
            <translation>Alarm: Die Maschine ist gesperrt.</translation>
        </message>
        <message>
            <source>Reset, Unlock and Set reference pose are in the status bar and the Machine panel.</source>
            <translation>Zurücksetzen, Entsperren und Referenzpose setzen finden Sie in der Statusleiste und im Maschinen-Bereich.</translation>
        </message>
    </context>
    <context>
        <name>GrblSetting</name>
        <message>
            <source>Step pulse time</source>
            <translation>Schrittimpulsdauer</translation>
        </message>
        <message>
            <source>Step idle delay (255: motors always on)</source>
            <translation>Verzögerung bis Motoren stromlos (255: immer an)</translation>
        </message>
        <message>
            <source>Step pulse invert (bit mask)</source>
            <translation>Schrittimpuls invertieren (Bitmaske)</translation>
        </message>
        <message>
            <source>Direction invert (bit mask)</source>
            <translation>Richtung invertieren (Bitmaske)</translation>
        </message>
        <message>
            <source>Invert step enable pin (on/off)</source>
            <translation>Enable-Pin invertieren (ein/aus)</translation>
        </message>
        <message>
            <source>Invert limit pins (on/off)</source>
            <translation>Endschalter-Pins invertieren (ein/aus)</translation>
        </message>
        <message>
            <source>Invert probe pin (on/off)</source>
            <translation>Tastereingang invertieren (ein/aus)</translation>
        </message>
        <message>
            <source>Status report options (bit mask)</source>
            <translation>Optionen des Statusberichts (Bitmaske)</translation>
        </message>
        <message>
            <source>Junction deviation</source>
            <translation>Übergangsabweichung (Junction Deviation)</translation>
        </message>
        <message>
            <source>Arc tolerance</source>
            <translation>Bogentoleranz</translation>
        </message>
        <message>
            <source>Report in inches (on/off)</source>
            <translation>Werte in Zoll melden (ein/aus)</translation>
        </message>
        <message>
            <source>Soft limits (on/off)</source>
            <translation>Software-Endlagen (ein/aus)</translation>
        </message>
        <message>
            <source>Hard limits (on/off)</source>
            <translation>Hardware-Endschalter (ein/aus)</translation>
        </message>
        <message>
            <source>Homing cycle (on/off)</source>
            <translation>Referenzfahrt (ein/aus)</translation>
        </message>
        <message>
            <source>Homing direction invert (bit mask)</source>
            <translation>Richtung der Referenzfahrt invertieren (Bitmaske)</translation>
        </message>
        <message>
            <source>Homing locate feed rate</source>
            <translation>Referenzfahrt: Vorschub beim Feinsuchen</translation>
        </message>
        <message>
            <source>Homing search seek rate</source>
            <translation>Referenzfahrt: Suchgeschwindigkeit</translation>
        </message>
        <message>
            <source>Homing switch debounce delay</source>
            <translation>Referenzschalter: Entprellzeit</translation>
        </message>
        <message>
            <source>Homing switch pull-off distance</source>
            <translation>Referenzschalter: Freifahrweg</translation>
        </message>
        <message>
            <source>Maximum spindle speed (largest S value)</source>
            <translation>Maximale Spindeldrehzahl (größter S-Wert)</translation>
        </message>
        <message>
            <source>Minimum spindle speed (smallest S value)</source>
            <translation>Minimale Spindeldrehzahl (kleinster S-Wert)</translation>
        </message>
        <message>
            <source>Laser mode (on/off)</source>
            <translation>Lasermodus (ein/aus)</translation>
        </message>
        <message>
            <source>Motor 1 (X) steps per degree</source>
            <translation>Motor 1 (X): Schritte pro Grad</translation>
        </message>
        <message>
            <source>Motor 2 (Y) steps per degree</source>
            <translation>Motor 2 (Y): Schritte pro Grad</translation>
        </message>
        <message>
            <source>Z steps per mm</source>
            <translation>Z: Schritte pro mm</translation>
        </message>
        <message>
            <source>Motor 1 (X) maximum rate</source>
            <translation>Motor 1 (X): Höchstgeschwindigkeit</translation>
        </message>
        <message>
            <source>Motor 2 (Y) maximum rate</source>
            <translation>Motor 2 (Y): Höchstgeschwindigkeit</translation>
        </message>
        <message>
            <source>Z maximum rate</source>
            <translation>Z: Höchstgeschwindigkeit</translation>
        </message>
        <message>
            <source>Motor 1 (X) acceleration</source>
            <translation>Motor 1 (X): Beschleunigung</translation>
        </message>
        <message>
            <source>Motor 2 (Y) acceleration</source>
            <translation>Motor 2 (Y): Beschleunigung</translation>
        </message>
        <message>
            <source>Z acceleration</source>
            <translation>Z: Beschleunigung</translation>
        </message>
        <message>
            <source>Motor 1 (X) maximum travel</source>
            <translation>Motor 1 (X): maximaler Verfahrweg</translation>
        </message>
        <message>
            <source>Motor 2 (Y) maximum travel</source>
            <translation>Motor 2 (Y): maximaler Verfahrweg</translation>
        </message>
        <message>
            <source>Z maximum travel</source>
            <translation>Z: maximaler Verfahrweg</translation>
        </message>
    </context>
    <context>
        <name>fivebar::widgets::calibration::RunProgressBox</name>
        <message>
            <source>Stop</source>
            <translation>Stopp</translation>
        </message>
        <message>
            <source>Stop cleanly: feed hold, then reset with the position kept and the pen up</source>
            <translation>Sauber anhalten: Vorschub anhalten, dann Reset mit gehaltener Position und angehobenem Stift</translation>
        </message>
        <message>
            <source>%1 % (%2)</source>
            <translation>%1 % (%2)</translation>
        </message>
        <message>
            <source>%1 left</source>
            <translation>noch %1</translation>
        </message>
    </context>
    <context>
        <name>fivebar::studio::HelpMenu</name>
        <message>
            <source>&amp;First job guide</source>
            <translation>&amp;Erster Auftrag: Anleitung</translation>
        </message>
        <message>
            <source>Connect, load a drawing, place it, preview and run: step by step</source>
            <translation>Verbinden, Zeichnung laden, platzieren, Vorschau ansehen und starten: Schritt für Schritt</translation>
        </message>
        <message>
            <source>&amp;Documentation</source>
            <translation>&amp;Dokumentation</translation>
        </message>
        <message>
            <source>Documentation</source>
            <translation>Dokumentation</translation>
        </message>
        <message>
            <source>The documentation file %1 is not installed. It is also on the project's pages, in the docs folder.</source>
            <translation>Die Dokumentationsdatei %1 ist nicht installiert. Sie steht auch auf den Seiten des Projekts, im Ordner docs.</translation>
        </message>
    </context>
</TS>

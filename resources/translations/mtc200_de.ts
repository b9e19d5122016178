<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="de" sourcelanguage="en">
<context>
    <name>CoreTerms</name>
    <message>
        <source>NC program restart</source>
        <translation>Satzvorlauf</translation>
    </message>
    <message>
        <source>REPOS</source>
        <translation>REPOS</translation>
    </message>
    <message>
        <source>Manual</source>
        <translation>Handbetrieb</translation>
    </message>
    <message>
        <source>Automatic</source>
        <translation>Automatik</translation>
    </message>
    <message>
        <source>Start</source>
        <translation>Start</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>Stop</translation>
    </message>
    <message>
        <source>Control reset</source>
        <translation>Steuerung rücksetzen</translation>
    </message>
    <message>
        <source>Single block</source>
        <translation>Einzelsatz</translation>
    </message>
    <message>
        <source>MDI</source>
        <translation>MDI</translation>
    </message>
    <message>
        <source>automatic</source>
        <translation>Automatik</translation>
    </message>
    <message>
        <source>manual</source>
        <translation>Handbetrieb</translation>
    </message>
    <message>
        <source>running</source>
        <translation>läuft</translation>
    </message>
    <message>
        <source>feed hold</source>
        <translation>Vorschub halt</translation>
    </message>
    <message>
        <source>M00 stop</source>
        <translation>M00-Halt</translation>
    </message>
    <message>
        <source>single block</source>
        <translation>Einzelsatz</translation>
    </message>
    <message>
        <source>waiting</source>
        <translation>wartet</translation>
    </message>
    <message>
        <source>restart</source>
        <translation>Satzvorlauf</translation>
    </message>
    <message>
        <source>error</source>
        <translation>Fehler</translation>
    </message>
    <message>
        <source>no program selected</source>
        <translation>kein Programm angewählt</translation>
    </message>
    <message>
        <source>ready: Start runs the program</source>
        <translation>bereit: Start führt das Programm aus</translation>
    </message>
    <message>
        <source>feed hold: Start continues</source>
        <translation>Vorschub halt: Start setzt fort</translation>
    </message>
    <message>
        <source>programmed stop (M00/M01): Start continues</source>
        <translation>programmierter Halt (M00/M01): Start setzt fort</translation>
    </message>
    <message>
        <source>single block: Start runs the next block</source>
        <translation>Einzelsatz: Start führt den nächsten Satz aus</translation>
    </message>
    <message>
        <source>waiting for an axis (GAX)</source>
        <translation>wartet auf eine Achse (GAX)</translation>
    </message>
    <message>
        <source>NC program restart: waiting for the SPS</source>
        <translation>Satzvorlauf: wartet auf die SPS</translation>
    </message>
    <message>
        <source>NC program restart active</source>
        <translation>Satzvorlauf aktiv</translation>
    </message>
    <message>
        <source>stopped by an error</source>
        <translation>durch einen Fehler angehalten</translation>
    </message>
    <message>
        <source>CW (M3)</source>
        <translation>rechts (M3)</translation>
    </message>
    <message>
        <source>CCW (M4)</source>
        <translation>links (M4)</translation>
    </message>
    <message>
        <source>stopped (M5)</source>
        <translation>steht (M5)</translation>
    </message>
    <message>
        <source>oriented (M19)</source>
        <translation>orientiert (M19)</translation>
    </message>
    <message>
        <source>interpolation</source>
        <translation>Interpolation</translation>
    </message>
    <message>
        <source>plane</source>
        <translation>Ebene</translation>
    </message>
    <message>
        <source>radius comp.</source>
        <translation>Radiuskorr.</translation>
    </message>
    <message>
        <source>zero offset</source>
        <translation>Nullpunktversch.</translation>
    </message>
    <message>
        <source>feed type</source>
        <translation>Vorschubart</translation>
    </message>
    <message>
        <source>dimensions</source>
        <translation>Maßangabe</translation>
    </message>
    <message>
        <source>radius/diameter</source>
        <translation>Radius/Durchm.</translation>
    </message>
    <message>
        <source>units</source>
        <translation>Maßeinheit</translation>
    </message>
    <message>
        <source>spindle speed</source>
        <translation>Spindeldrehzahl</translation>
    </message>
    <message>
        <source>acceleration</source>
        <translation>Beschleunigung</translation>
    </message>
    <message>
        <source>exact stop</source>
        <translation>Genauhalt</translation>
    </message>
    <message>
        <source>length comp.</source>
        <translation>Längenkorr.</translation>
    </message>
    <message>
        <source>transformation</source>
        <translation>Transformation</translation>
    </message>
</context>
<context>
    <name>KeyMap</name>
    <message>
        <source>Soft keys of the current screen (labels in the bar at the bottom)</source>
        <translation>Softkeys der angezeigten Maske (Beschriftung in der Leiste unten)</translation>
    </message>
    <message>
        <source>Back to the main menu of the station</source>
        <translation>Zurück zum Hauptmenü der Station</translation>
    </message>
    <message>
        <source>Ctrl+PgUp / Ctrl+PgDn</source>
        <translation>Strg+Bild↑ / Strg+Bild↓</translation>
    </message>
    <message>
        <source>Previous / next station (process); each keeps its screen</source>
        <translation>Vorige / nächste Station (Prozess); jede behält ihre Maske</translation>
    </message>
    <message>
        <source>Base screen of the station: positions, feed, spindles, running block</source>
        <translation>Grundbild der Station: Positionen, Vorschub, Spindeln, laufender Satz</translation>
    </message>
    <message>
        <source>Help for the screen shown, and every key</source>
        <translation>Hilfe zur angezeigten Maske und alle Tasten</translation>
    </message>
    <message>
        <source>Tab / Shift+Tab</source>
        <translation>Tab / Umschalt+Tab</translation>
    </message>
    <message>
        <source>Move the focus between fields of a screen</source>
        <translation>Fokus zwischen den Feldern einer Maske bewegen</translation>
    </message>
    <message>
        <source>Machine control key &apos;%1&apos;</source>
        <translation>Maschinensteuertaste „%1“</translation>
    </message>
    <message>
        <source>Feed override one step up / down (0 … the machine&apos;s maximum, shown under the M keys)</source>
        <translation>Vorschub-Override eine Stufe höher / tiefer (0 … Maximum der Maschine, unter den M-Tasten angezeigt)</translation>
    </message>
    <message>
        <source>Rapid traverse override one step up / down (0, 1, 10, 25, 50, 100 %)</source>
        <translation>Eilgang-Override eine Stufe höher / tiefer (0, 1, 10, 25, 50, 100 %)</translation>
    </message>
    <message>
        <source>Simulation speed: ×1 → ×10 → as fast as possible (shown in the header)</source>
        <translation>Simulationstempo: ×1 → ×10 → so schnell wie möglich (in der Kopfzeile angezeigt)</translation>
    </message>
</context>
<context>
    <name>PanelOptions</name>
    <message>
        <source>MTC200 operator panel simulator</source>
        <translation>MTC200-Bedienfeld-Simulator</translation>
    </message>
    <message>
        <source>Machine configuration file (default: built-in demo cell).</source>
        <translation>Maschinenkonfigurationsdatei (Vorgabe: eingebaute Demo-Zelle).</translation>
    </message>
    <message>
        <source>Program directory with NuxxYzzz.DAT files (default: demo programs).</source>
        <translation>Programmverzeichnis mit NuxxYzzz.DAT-Dateien (Vorgabe: Demo-Programme).</translation>
    </message>
    <message>
        <source>Station (process) shown first.</source>
        <translation>Zuerst angezeigte Station (Prozess).</translation>
    </message>
    <message>
        <source>Program to select: a number or a source file.</source>
        <translation>Anzuwählendes Programm: eine Nummer oder eine Quelldatei.</translation>
    </message>
    <message>
        <source>Screen shown first (restart, programs, signals, help, ...).</source>
        <translation>Zuerst angezeigte Maske (restart, programs, signals, help, ...).</translation>
    </message>
    <message>
        <source>Render the screen once, write a PNG to FILE and exit.</source>
        <translation>Maske einmal zeichnen, als PNG nach FILE schreiben und beenden.</translation>
    </message>
    <message>
        <source>Run the selected program of the station to its end in simulated time before the window appears (e.g. a trend for --screenshot).</source>
        <translation>Das angewählte Programm der Station in simulierter Zeit bis zum Ende ausführen, bevor das Fenster erscheint (z. B. für einen Trend mit --screenshot).</translation>
    </message>
    <message>
        <source>Simulation speed: 1 (real time, default), 10 (ten times) or max (as fast as possible); the Speed key changes it.</source>
        <translation>Simulationstempo: 1 (Echtzeit, Vorgabe), 10 (zehnfach) oder max (so schnell wie möglich); die Tempo-Taste ändert es.</translation>
    </message>
    <message>
        <source>Machine data file (default: $XDG_STATE_HOME/mtc200/machine-data/&lt;cell&gt;.mdt; &apos;-&apos; keeps nothing).</source>
        <translation>Maschinendatendatei (Vorgabe: $XDG_STATE_HOME/mtc200/machine-data/&lt;Zelle&gt;.mdt; &apos;-&apos; speichert nichts).</translation>
    </message>
    <message>
        <source>Language of the panel: de (German) or en (English). Default: the language chosen on the help screen, else the desk&apos;s locale (German for de_*).</source>
        <translation>Sprache des Bedienfelds: de (Deutsch) oder en (Englisch). Vorgabe: die in der Hilfe gewählte Sprache, sonst die Locale des Arbeitsplatzes (Deutsch bei de_*).</translation>
    </message>
    <message>
        <source>unexpected argument: %1</source>
        <translation>unerwartetes Argument: %1</translation>
    </message>
    <message>
        <source>--data needs a file (or &apos;-&apos; for none)</source>
        <translation>--data braucht eine Datei (oder &apos;-&apos; für keine)</translation>
    </message>
    <message>
        <source>--speed needs 1, 10 or max, got &apos;%1&apos;</source>
        <translation>--speed braucht 1, 10 oder max, nicht &apos;%1&apos;</translation>
    </message>
    <message>
        <source>--lang needs de or en, got &apos;%1&apos;</source>
        <translation>--lang braucht de oder en, nicht &apos;%1&apos;</translation>
    </message>
    <message>
        <source>--process needs a process number &gt;= 0, got &apos;%1&apos;</source>
        <translation>--process braucht eine Prozessnummer &gt;= 0, nicht &apos;%1&apos;</translation>
    </message>
</context>
<context>
    <name>ScreenHelp</name>
    <message>
        <source>Leads to every screen of the station.</source>
        <translation>Führt zu jeder Maske der Station.</translation>
    </message>
    <message>
        <source>↑ / ↓, Enter</source>
        <translation>↑ / ↓, Eingabe</translation>
    </message>
    <message>
        <source>choose a screen</source>
        <translation>Maske wählen</translation>
    </message>
    <message>
        <source>The base screen: where every axis is (workpiece and machine coordinates, distance to go), feeds and overrides, spindles, the tool and its edge, the active G functions, the zero offset and the block the machine executes with its neighbours. In manual mode the axes are jogged here.</source>
        <translation>Das Grundbild: wo jede Achse steht (Werkstück- und Maschinenkoordinaten, Restweg), Vorschübe und Override, Spindeln, Werkzeug und Schneide, die aktiven G-Funktionen, die Nullpunktverschiebung und der Satz, den die Maschine ausführt, mit seinen Nachbarn. Im Handbetrieb werden die Achsen hier verfahren.</translation>
    </message>
    <message>
        <source>the simulator&apos;s own layout (docs/DECISIONS.md D-014)</source>
        <translation>eigene Gestaltung des Simulators (docs/DECISIONS.md D-014)</translation>
    </message>
    <message>
        <source>↑ / ↓</source>
        <translation>↑ / ↓</translation>
    </message>
    <message>
        <source>choose the axis to jog (manual mode)</source>
        <translation>zu verfahrende Achse wählen (Handbetrieb)</translation>
    </message>
    <message>
        <source>+ / −</source>
        <translation>+ / −</translation>
    </message>
    <message>
        <source>jog the axis by the step, or while held (continuous)</source>
        <translation>Achse um das Schrittmaß verfahren, oder solange gedrückt (kontinuierlich)</translation>
    </message>
    <message>
        <source>mouse wheel</source>
        <translation>Mausrad</translation>
    </message>
    <message>
        <source>handwheel: one detent is one step</source>
        <translation>Handrad: eine Raste ist ein Schritt</translation>
    </message>
    <message>
        <source>3 / 4 / 5</source>
        <translation>3 / 4 / 5</translation>
    </message>
    <message>
        <source>spindle clockwise / counter-clockwise / stop (manual mode)</source>
        <translation>Spindel rechts / links / halt (Handbetrieb)</translation>
    </message>
    <message>
        <source>PgUp / PgDn</source>
        <translation>Bild↑ / Bild↓</translation>
    </message>
    <message>
        <source>spindle speed ±100 rpm (manual mode)</source>
        <translation>Spindeldrehzahl ±100 U/min (Handbetrieb)</translation>
    </message>
    <message>
        <source>The station&apos;s programs with the compiler status bit ( , N, C, E) and the listing of the one under the cursor; selects the program to run.</source>
        <translation>Die Programme der Station mit dem Compiler-Statusbit ( , N, C, E) und dem Listing des Programms unter dem Cursor; wählt das auszuführende Programm an.</translation>
    </message>
    <message>
        <source>seed 001 ch. 7</source>
        <translation>Seed 001 Kap. 7</translation>
    </message>
    <message>
        <source>move the cursor</source>
        <translation>Cursor bewegen</translation>
    </message>
    <message>
        <source>Enter</source>
        <translation>Eingabe</translation>
    </message>
    <message>
        <source>select the program</source>
        <translation>Programm anwählen</translation>
    </message>
    <message>
        <source>The cell&apos;s NC options: compiler active, user compilers 1–4, syntax check and the global macros, written at once to NC_OPTIONS.CFG and GLOBAL_MACROS.MAC.</source>
        <translation>Die NC-Optionen der Zelle: Compiler aktiv, Anwender-Compiler 1–4, Syntaxprüfung und die globalen Makros, sofort in NC_OPTIONS.CFG und GLOBAL_MACROS.MAC geschrieben.</translation>
    </message>
    <message>
        <source>seed 001 ch. 4, 7, 8</source>
        <translation>Seed 001 Kap. 4, 7, 8</translation>
    </message>
    <message>
        <source>change the row under the cursor</source>
        <translation>Zeile unter dem Cursor ändern</translation>
    </message>
    <message>
        <source>Delete</source>
        <translation>Entf</translation>
    </message>
    <message>
        <source>delete the macro under the cursor</source>
        <translation>Makro unter dem Cursor löschen</translation>
    </message>
    <message>
        <source>Escape</source>
        <translation>Esc</translation>
    </message>
    <message>
        <source>cancel the input line</source>
        <translation>Eingabezeile verwerfen</translation>
    </message>
    <message>
        <source>The NC program editor with highlighting, line numbers and the block of the cursor; saves atomically and compiles.</source>
        <translation>Der NC-Programm-Editor mit Hervorhebung, Zeilennummern und dem Satz des Cursors; speichert atomar und compiliert.</translation>
    </message>
    <message>
        <source>seed 001 ch. 10 (source program), ch. 9 (errors)</source>
        <translation>Seed 001 Kap. 10 (Quellprogramm), Kap. 9 (Fehler)</translation>
    </message>
    <message>
        <source>Ctrl+S</source>
        <translation>Strg+S</translation>
    </message>
    <message>
        <source>save</source>
        <translation>speichern</translation>
    </message>
    <message>
        <source>Ctrl+E</source>
        <translation>Strg+E</translation>
    </message>
    <message>
        <source>error display</source>
        <translation>Fehleranzeige</translation>
    </message>
    <message>
        <source>Ctrl+W</source>
        <translation>Strg+W</translation>
    </message>
    <message>
        <source>graphical NC editor</source>
        <translation>grafischer NC-Editor</translation>
    </message>
    <message>
        <source>The error window: one brief message per line (compiler, runtime, restart, MDI) with program and block; the additional text on request.</source>
        <translation>Das Fehlerfenster: eine Kurzmeldung je Zeile (Compiler, Laufzeit, Satzvorlauf, MDI) mit Programm und Satz; der Zusatztext auf Wunsch.</translation>
    </message>
    <message>
        <source>seed 001 ch. 9</source>
        <translation>Seed 001 Kap. 9</translation>
    </message>
    <message>
        <source>open the editor at the message&apos;s line</source>
        <translation>Editor an der Zeile der Meldung öffnen</translation>
    </message>
    <message>
        <source>The graphical NC editor: contours, forms and cycles as rows with their values and a live drawing; Exit writes them back into the program.</source>
        <translation>Der grafische NC-Editor: Konturen, Formen und Zyklen als Zeilen mit ihren Werten und mitlaufender Zeichnung; Exit schreibt sie ins Programm zurück.</translation>
    </message>
    <message>
        <source>seed 001 ch. 3</source>
        <translation>Seed 001 Kap. 3</translation>
    </message>
    <message>
        <source>choose a row</source>
        <translation>Zeile wählen</translation>
    </message>
    <message>
        <source>take the value</source>
        <translation>Wert übernehmen</translation>
    </message>
    <message>
        <source>The source program beside the compiled runtime program; inserted blocks keep their numbers, compensation corners are marked →.</source>
        <translation>Das Quellprogramm neben dem compilierten Laufzeitprogramm; eingefügte Sätze behalten ihre Nummern, Korrekturecken sind mit → markiert.</translation>
    </message>
    <message>
        <source>seed 001 ch. 1, 10, 11</source>
        <translation>Seed 001 Kap. 1, 10, 11</translation>
    </message>
    <message>
        <source>move through the compiled program</source>
        <translation>durch das compilierte Programm blättern</translation>
    </message>
    <message>
        <source>Manual data input: a few NC blocks typed here run from the station&apos;s current state when Start is pressed in MDI mode (Shift+F9). The input stays until an entry ran to its end.</source>
        <translation>Manuelle Dateneingabe: einige hier eingegebene NC-Sätze laufen vom aktuellen Zustand der Station aus, wenn in der Betriebsart MDI (Umschalt+F9) Start gedrückt wird. Die Eingabe bleibt, bis eine Eingabe zu Ende gelaufen ist.</translation>
    </message>
    <message>
        <source>seed 001 ch. 4, 12</source>
        <translation>Seed 001 Kap. 4, 12</translation>
    </message>
    <message>
        <source>Shift+F9, Shift+F5</source>
        <translation>Umschalt+F9, Umschalt+F5</translation>
    </message>
    <message>
        <source>MDI mode, then Start runs the input</source>
        <translation>Betriebsart MDI, dann führt Start die Eingabe aus</translation>
    </message>
    <message>
        <source>The station&apos;s NC and SPS interface signals and a log of every change.</source>
        <translation>Die NC- und SPS-Schnittstellensignale der Station und ein Protokoll jeder Änderung.</translation>
    </message>
    <message>
        <source>seed 000 ch. 6</source>
        <translation>Seed 000 Kap. 6</translation>
    </message>
    <message>
        <source>Machine data pages 30, 60, 61 and the user pages with number, title, value and unit; values are checked against range, type and write protection.</source>
        <translation>Maschinendaten-Seiten 30, 60, 61 und die Anwenderseiten mit Nummer, Titel, Wert und Einheit; Werte werden gegen Bereich, Typ und Schreibschutz geprüft.</translation>
    </message>
    <message>
        <source>seed 000 ch. 4; seed 002 ch. 5</source>
        <translation>Seed 000 Kap. 4; Seed 002 Kap. 5</translation>
    </message>
    <message>
        <source>← / →</source>
        <translation>← / →</translation>
    </message>
    <message>
        <source>previous / next page</source>
        <translation>vorige / nächste Seite</translation>
    </message>
    <message>
        <source>edit the value under the cursor</source>
        <translation>Wert unter dem Cursor bearbeiten</translation>
    </message>
    <message>
        <source>The tool list of the station&apos;s process, one row per cutting edge; every value is checked and saved at once beside the machine data file.</source>
        <translation>Die Werkzeugliste des Prozesses der Station, eine Zeile je Schneide; jeder Wert wird geprüft und sofort neben der Maschinendatendatei gespeichert.</translation>
    </message>
    <message>
        <source>the simulator&apos;s own table (docs/TOOL-DATA.md)</source>
        <translation>eigene Tabelle des Simulators (docs/TOOL-DATA.md)</translation>
    </message>
    <message>
        <source>cursor keys, Home / End</source>
        <translation>Cursortasten, Pos1 / Ende</translation>
    </message>
    <message>
        <source>move the cell</source>
        <translation>Zelle bewegen</translation>
    </message>
    <message>
        <source>edit the cell</source>
        <translation>Zelle bearbeiten</translation>
    </message>
    <message>
        <source>The zero offsets G54..G59 of the station&apos;s process, one column per axis definition.</source>
        <translation>Die Nullpunktverschiebungen G54..G59 des Prozesses der Station, eine Spalte je Achsdefinition.</translation>
    </message>
    <message>
        <source>seed 003, 3.5</source>
        <translation>Seed 003, 3.5</translation>
    </message>
    <message>
        <source>cursor keys</source>
        <translation>Cursortasten</translation>
    </message>
    <message>
        <source>The adaptive feed control&apos;s trend over simulated time: torques, limits, feed reduction and the signals.</source>
        <translation>Der Verlauf der adaptiven Vorschubregelung über der simulierten Zeit: Momente, Grenzen, Vorschubreduzierung und die Signale.</translation>
    </message>
    <message>
        <source>seed 002 Fig. 2-1, 6-1</source>
        <translation>Seed 002 Bild 2-1, 6-1</translation>
    </message>
    <message>
        <source>Every key of the panel and the soft keys of each screen.</source>
        <translation>Jede Taste des Bedienfelds und die Softkeys jeder Maske.</translation>
    </message>
    <message>
        <source>NC program restart: choose the target block anywhere in the program tree, follow jumps and calls with Plane+ / Plane−, then start the computing process.</source>
        <translation>Satzvorlauf: den Zielsatz irgendwo im Programmbaum wählen, Sprüngen und Aufrufen mit Ebene+ / Ebene− folgen, dann den Rechenlauf starten.</translation>
    </message>
    <message>
        <source>seed 000 ch. 2.3–2.6</source>
        <translation>Seed 000 Kap. 2.3–2.6</translation>
    </message>
    <message>
        <source>↑ / ↓, PgUp / PgDn</source>
        <translation>↑ / ↓, Bild↑ / Bild↓</translation>
    </message>
    <message>
        <source>accept the target block</source>
        <translation>Zielsatz übernehmen</translation>
    </message>
    <message>
        <source>The state the computing process computed for the target beside the machine&apos;s state before, with the differences and the verification of the target.</source>
        <translation>Der vom Rechenlauf für das Ziel berechnete Zustand neben dem vorherigen Zustand der Maschine, mit den Unterschieden und der Prüfung des Ziels.</translation>
    </message>
    <message>
        <source>seed 000 ch. 2.7, 2.8</source>
        <translation>Seed 000 Kap. 2.7, 2.8</translation>
    </message>
    <message>
        <source>Distance of every axis to the re-entry point while ADJUST and REPOS run; jogging in manual mode between them.</source>
        <translation>Abstand jeder Achse zum Wiedereintrittspunkt, während ADJUST und REPOS laufen; dazwischen Verfahren im Handbetrieb.</translation>
    </message>
    <message>
        <source>seed 000 ch. 2.8, 2.9, Fig. 2-4</source>
        <translation>Seed 000 Kap. 2.8, 2.9, Bild 2-4</translation>
    </message>
    <message>
        <source>The selected program&apos;s path in 3D (2D without OpenGL): rapid, feed and arcs, the running block, the restart&apos;s target and REPOS path, the programmed contour beside the tool-centre path under compensation.</source>
        <translation>Die Bahn des angewählten Programms in 3D (2D ohne OpenGL): Eilgang, Vorschub und Kreise, der laufende Satz, Ziel und REPOS-Weg des Satzvorlaufs, die programmierte Kontur neben der Werkzeugmittelpunktsbahn unter Korrektur.</translation>
    </message>
    <message>
        <source>the simulator&apos;s own view (docs/decisions/toolpath.md)</source>
        <translation>eigene Ansicht des Simulators (docs/decisions/toolpath.md)</translation>
    </message>
    <message>
        <source>mouse</source>
        <translation>Maus</translation>
    </message>
    <message>
        <source>rotate, pan and zoom; a click picks a block</source>
        <translation>drehen, verschieben und zoomen; ein Klick wählt einen Satz</translation>
    </message>
</context>
<context>
    <name>ScreenTitle</name>
    <message>
        <source>Adaptive feed trend</source>
        <translation>Adaptive Vorschub­regelung: Verlauf</translation>
    </message>
    <message>
        <source>Program editor</source>
        <translation>Programm-Editor</translation>
    </message>
    <message>
        <source>Error display</source>
        <translation>Fehlerfenster</translation>
    </message>
    <message>
        <source>Graphical NC editor (GNE)</source>
        <translation>Grafischer NC-Editor (GNE)</translation>
    </message>
    <message>
        <source>Help</source>
        <translation>Hilfe</translation>
    </message>
    <message>
        <source>Machine data</source>
        <translation>Maschinen­daten</translation>
    </message>
    <message>
        <source>MDI (manual data input)</source>
        <translation>MDI (Hand­eingabe)</translation>
    </message>
    <message>
        <source>Main menu</source>
        <translation>Hauptmenü</translation>
    </message>
    <message>
        <source>NC options</source>
        <translation>NC-Optionen</translation>
    </message>
    <message>
        <source>Base screen (position)</source>
        <translation>Grundbild (Position)</translation>
    </message>
    <message>
        <source>Repositioning</source>
        <translation>Wieder­anfahren (REPOS)</translation>
    </message>
    <message>
        <source>NC program restart: result</source>
        <translation>Satzvorlauf: Ergebnis</translation>
    </message>
    <message>
        <source>NC program restart</source>
        <translation>Satzvorlauf</translation>
    </message>
    <message>
        <source>Runtime program</source>
        <translation>Laufzeitprogramm</translation>
    </message>
    <message>
        <source>Program directory</source>
        <translation>Programm­verzeichnis</translation>
    </message>
    <message>
        <source>Interface signals</source>
        <translation>Schnitt­stellen­signale</translation>
    </message>
    <message>
        <source>Tool table</source>
        <translation>Werkzeug­tabelle</translation>
    </message>
    <message>
        <source>Zero offsets</source>
        <translation>Nullpunkt­verschiebungen</translation>
    </message>
    <message>
        <source>Toolpath graphics</source>
        <translation>Bahn­grafik</translation>
    </message>
</context>
<context>
    <name>mtc::hmi::ErrorLog</name>
    <message>
        <source>compiler</source>
        <translation>Compiler</translation>
    </message>
    <message>
        <source>runtime</source>
        <translation>Laufzeit</translation>
    </message>
    <message>
        <source>restart</source>
        <translation>Satzvorlauf</translation>
    </message>
    <message>
        <source>MDI</source>
        <translation>MDI</translation>
    </message>
</context>
<context>
    <name>mtc::hmi::MachineKeyBar</name>
    <message>
        <source>Feed override</source>
        <translation>Vorschub-Override</translation>
    </message>
    <message>
        <source>Rapid override</source>
        <translation>Eilgang-Override</translation>
    </message>
    <message>
        <source>%1: simulation speed</source>
        <translation>%1: Simulationstempo</translation>
    </message>
    <message>
        <source>%1 up (%2)</source>
        <translation>%1 höher (%2)</translation>
    </message>
    <message>
        <source>%1 down (%2)</source>
        <translation>%1 tiefer (%2)</translation>
    </message>
    <message>
        <source>Speed %1</source>
        <translation>Tempo %1</translation>
    </message>
</context>
<context>
    <name>mtc::hmi::PanelWindow</name>
    <message>
        <source>MTC200 panel simulator</source>
        <translation>MTC200-Bedienfeld-Simulator</translation>
    </message>
    <message>
        <source>User compiler from the program folder</source>
        <translation>Anwender-Compiler aus dem Programmordner</translation>
    </message>
    <message>
        <source>User compiler %1 of the program folder
%2
wants to run this command (from its %3):

%4

It did not come from this desk. Run it now and from now on for this folder?</source>
        <translation>Anwender-Compiler %1 des Programmordners
%2
will diesen Befehl ausführen (aus seiner %3):

%4

Er stammt nicht von diesem Arbeitsplatz. Jetzt und künftig für diesen Ordner ausführen?</translation>
    </message>
</context>
<context>
    <name>mtc::hmi::StatusHeader</name>
    <message>
        <source>Station %1: %2</source>
        <translation>Station %1: %2</translation>
    </message>
    <message>
        <source>Mode: %1</source>
        <translation>Betriebsart: %1</translation>
    </message>
    <message>
        <source>Program: none</source>
        <translation>Programm: keines</translation>
    </message>
    <message>
        <source>Program: %1</source>
        <translation>Programm: %1</translation>
    </message>
    <message>
        <source>Block: %1</source>
        <translation>Satz: %1</translation>
    </message>
    <message>
        <source>Speed %1</source>
        <translation>Tempo %1</translation>
    </message>
    <message>
        <source>Alarm: %1</source>
        <translation>Alarm: %1</translation>
    </message>
    <message>
        <source>No alarm</source>
        <translation>Kein Alarm</translation>
    </message>
</context>
<context>
    <name>mtc::screens::ErrorsScreen</name>
    <message>
        <source>W</source>
        <comment>warning</comment>
        <translation>W</translation>
    </message>
    <message>
        <source>E</source>
        <comment>error</comment>
        <translation>F</translation>
    </message>
    <message>
        <source>MDI input line %1</source>
        <translation>MDI-Eingabe Zeile %1</translation>
    </message>
    <message>
        <source>source line %1</source>
        <translation>Quelltext Zeile %1</translation>
    </message>
    <message>
        <source>No errors.</source>
        <translation>Keine Fehler.</translation>
    </message>
    <message numerus="yes">
        <source>%n message(s). Enter: go to the block in the editor; F2: additional text</source>
        <translation>
            <numerusform>%n Meldung. Eingabe: zum Satz im Editor; F2: Zusatztext</numerusform>
            <numerusform>%n Meldungen. Eingabe: zum Satz im Editor; F2: Zusatztext</numerusform>
        </translation>
    </message>
    <message>
        <source>This message belongs to no program of this station.</source>
        <translation>Diese Meldung gehört zu keinem Programm dieser Station.</translation>
    </message>
    <message>
        <source>Go to
block</source>
        <translation>Gehe zu
Satz</translation>
    </message>
    <message>
        <source>Additional
text</source>
        <translation>Zusatz-
text</translation>
    </message>
    <message>
        <source>Clear
runtime</source>
        <translation>Laufzeit
löschen</translation>
    </message>
    <message>
        <source>Back</source>
        <translation>Zurück</translation>
    </message>
</context>
<context>
    <name>mtc::screens::HelpScreen</name>
    <message>
        <source>Reproduces: %1</source>
        <translation>Bildet nach: %1</translation>
    </message>
    <message>
        <source>Panel keys</source>
        <translation>Tasten des Bedienfelds</translation>
    </message>
    <message>
        <source>Language</source>
        <translation>Sprache</translation>
    </message>
    <message>
        <source>The panel is shown in %1.</source>
        <translation>Das Bedienfeld wird auf %1 angezeigt.</translation>
    </message>
    <message>
        <source>This desk has no language of its own: the panel follows the desk&apos;s locale (German for de_*) unless started with --lang de|en.</source>
        <translation>Dieser Arbeitsplatz hat keine eigene Sprache: das Bedienfeld folgt seiner Locale (Deutsch bei de_*), außer beim Start mit --lang de|en.</translation>
    </message>
    <message>
        <source>This desk starts the panel in %1 (unless started with --lang de|en).</source>
        <translation>Dieser Arbeitsplatz startet das Bedienfeld auf %1 (außer beim Start mit --lang de|en).</translation>
    </message>
    <message>
        <source>F6 and F7 store the language for the next start.</source>
        <translation>F6 und F7 speichern die Sprache für den nächsten Start.</translation>
    </message>
    <message>
        <source>Back</source>
        <translation>Zurück</translation>
    </message>
</context>
<context>
    <name>mtc::screens::MenuScreen</name>
    <message>
        <source>Select a screen (cursor keys + Enter, or its soft key):</source>
        <translation>Maske wählen (Cursortasten + Eingabe oder ihr Softkey):</translation>
    </message>
    <message>
        <source>More…</source>
        <translation>Weitere…</translation>
    </message>
</context>
<context>
    <name>mtc::screens::PositionScreen</name>
    <message>
        <source>Axis</source>
        <translation>Achse</translation>
    </message>
    <message>
        <source>Workpiece</source>
        <translation>Werkstück</translation>
    </message>
    <message>
        <source>Machine</source>
        <translation>Maschine</translation>
    </message>
    <message>
        <source>To go</source>
        <translation>Restweg</translation>
    </message>
    <message>
        <source>Feed and override</source>
        <translation>Vorschub und Override</translation>
    </message>
    <message>
        <source>Spindles (programmed / actual)</source>
        <translation>Spindeln (programmiert / Ist)</translation>
    </message>
    <message>
        <source>Tool and edge</source>
        <translation>Werkzeug und Schneide</translation>
    </message>
    <message>
        <source>Program</source>
        <translation>Programm</translation>
    </message>
    <message>
        <source>Active G functions and zero offset</source>
        <translation>Aktive G-Funktionen und Nullpunktverschiebung</translation>
    </message>
    <message>
        <source>Jog step
continuous</source>
        <translation>Schrittmaß
kontinuierlich</translation>
    </message>
    <message>
        <source>Jog step
%1</source>
        <translation>Schrittmaß
%1</translation>
    </message>
    <message>
        <source>Rapid
on</source>
        <translation>Eilgang
ein</translation>
    </message>
    <message>
        <source>Rapid
off</source>
        <translation>Eilgang
aus</translation>
    </message>
    <message>
        <source>Program
directory</source>
        <translation>Programm­verzeichnis</translation>
    </message>
    <message>
        <source>Error
display</source>
        <translation>Fehler­fenster</translation>
    </message>
    <message>
        <source>MDI</source>
        <translation>MDI</translation>
    </message>
    <message>
        <source>Toolpath</source>
        <translation>Bahngrafik</translation>
    </message>
    <message>
        <source>NC program
restart</source>
        <translation>Satzvorlauf</translation>
    </message>
    <message>
        <source>Main menu</source>
        <translation>Hauptmenü</translation>
    </message>
    <message>
        <source>%1: 3 / 4 / 5 = M3 / M4 / M5, PgUp / PgDn = speed ±100 rpm</source>
        <translation>%1: 3 / 4 / 5 = M3 / M4 / M5, Bild↑ / Bild↓ = Drehzahl ±100 U/min</translation>
    </message>
    <message>
        <source>Manual: jog %1 with + / − (↑/↓ axis), %2%3; wheel = handwheel%4</source>
        <translation>Handbetrieb: %1 mit + / − verfahren (↑/↓ Achse), %2%3; Mausrad = Handrad%4</translation>
    </message>
    <message>
        <source>continuous while held</source>
        <translation>kontinuierlich solange gedrückt</translation>
    </message>
    <message>
        <source>step %1</source>
        <translation>Schrittmaß %1</translation>
    </message>
    <message>
        <source>, rapid</source>
        <translation>, Eilgang</translation>
    </message>
    <message>
        <source>mm/rev</source>
        <translation>mm/U</translation>
    </message>
    <message>
        <source>F programmed %1 %2
F actual     %3 mm/min</source>
        <translation>F programmiert %1 %2
F Ist         %3 mm/min</translation>
    </message>
    <message>
        <source>Override F %1</source>
        <translation>Override F %1</translation>
    </message>
    <message>
        <source>%1 %2 / %3 rpm %4</source>
        <translation>%1 %2 / %3 U/min %4</translation>
    </message>
    <message>
        <source>(rotary axis)</source>
        <translation>(Rundachse)</translation>
    </message>
    <message>
        <source>none</source>
        <translation>keine</translation>
    </message>
    <message>
        <source>no tool (T0)</source>
        <translation>kein Werkzeug (T0)</translation>
    </message>
    <message>
        <source>(not in the tool list)</source>
        <translation>(nicht in der Werkzeugliste)</translation>
    </message>
    <message>
        <source>R %1  position %5
L1 %2  L2 %3  L3 %4</source>
        <translation>R %1  Lage %5
L1 %2  L2 %3  L3 %4</translation>
    </message>
    <message>
        <source>Zero offset G53 (machine coordinates)</source>
        <translation>Nullpunktverschiebung G53 (Maschinenkoordinaten)</translation>
    </message>
    <message>
        <source>Zero offset G%1:%2</source>
        <translation>Nullpunktverschiebung G%1:%2</translation>
    </message>
    <message>
        <source>No block</source>
        <translation>Kein Satz</translation>
    </message>
    <message>
        <source>Program 99 (subroutine library)</source>
        <translation>Programm 99 (Unterprogrammbibliothek)</translation>
    </message>
    <message>
        <source>Program %1</source>
        <translation>Programm %1</translation>
    </message>
    <message>
        <source>, main level</source>
        <translation>, Hauptebene</translation>
    </message>
    <message>
        <source>, call level %1</source>
        <translation>, Aufrufebene %1</translation>
    </message>
</context>
</TS>

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
    <name>GneModel</name>
    <message>
        <source>nothing selected</source>
        <translation>nichts ausgewählt</translation>
    </message>
    <message>
        <source>%1 cannot be inserted here</source>
        <translation>%1 kann hier nicht eingefügt werden</translation>
    </message>
    <message>
        <source>nothing to delete</source>
        <translation>nichts zu löschen</translation>
    </message>
    <message>
        <source>when read, line %1: %2</source>
        <translation>beim Lesen, Zeile %1: %2</translation>
    </message>
    <message>
        <source>row %1 (%2): the contour needs a START with both coordinates</source>
        <translation>Zeile %1 (%2): die Kontur braucht ein START mit beiden Koordinaten</translation>
    </message>
    <message>
        <source>row %1 (%2): %3</source>
        <translation>Zeile %1 (%2): %3</translation>
    </message>
    <message>
        <source>the section does not expand: %1</source>
        <translation>der Abschnitt lässt sich nicht auflösen: %1</translation>
    </message>
    <message>
        <source>NC blocks need a machining cycle: insert a CYCLE_xx for the contour, or save as function call</source>
        <translation>NC-Sätze brauchen einen Bearbeitungszyklus: einen CYCLE_xx für die Kontur einfügen oder als Funktionsaufruf speichern</translation>
    </message>
    <message>
        <source>end point, 1st axis</source>
        <translation>Endpunkt, 1. Achse</translation>
    </message>
    <message>
        <source>end point, 2nd axis</source>
        <translation>Endpunkt, 2. Achse</translation>
    </message>
    <message>
        <source>1 = tangential to the previous element</source>
        <translation>1 = tangential zum vorigen Element</translation>
    </message>
    <message>
        <source>chosen solution (0 = first)</source>
        <translation>gewählte Lösung (0 = erste)</translation>
    </message>
    <message>
        <source>start point, 1st axis</source>
        <translation>Startpunkt, 1. Achse</translation>
    </message>
    <message>
        <source>start point, 2nd axis</source>
        <translation>Startpunkt, 2. Achse</translation>
    </message>
    <message>
        <source>direction in degrees from the 1st axis</source>
        <translation>Richtung in Grad zur 1. Achse</translation>
    </message>
    <message>
        <source>length of the line</source>
        <translation>Länge der Geraden</translation>
    </message>
    <message>
        <source>centre, 1st axis (absolute)</source>
        <translation>Mittelpunkt, 1. Achse (absolut)</translation>
    </message>
    <message>
        <source>centre, 2nd axis (absolute)</source>
        <translation>Mittelpunkt, 2. Achse (absolut)</translation>
    </message>
    <message>
        <source>radius of the arc</source>
        <translation>Radius des Kreisbogens</translation>
    </message>
    <message>
        <source>radius of the rounding</source>
        <translation>Radius der Rundung</translation>
    </message>
    <message>
        <source>width of the chamfer</source>
        <translation>Breite der Fase</translation>
    </message>
    <message>
        <source>DIN 509 form: E or F</source>
        <translation>Form nach DIN 509: E oder F</translation>
    </message>
    <message>
        <source>radius (empty = DIN 509 table)</source>
        <translation>Radius (leer = Tabelle DIN 509)</translation>
    </message>
    <message>
        <source>depth into the cylinder t1</source>
        <translation>Tiefe in den Zylinder t1</translation>
    </message>
    <message>
        <source>width (empty = DIN 509 table)</source>
        <translation>Breite (leer = Tabelle DIN 509)</translation>
    </message>
    <message>
        <source>form F: depth into the face t2</source>
        <translation>Form F: Tiefe in die Planfläche t2</translation>
    </message>
    <message>
        <source>%1 must be given</source>
        <translation>%1 muss angegeben werden</translation>
    </message>
    <message>
        <source>%1: &apos;%2&apos; is not a number</source>
        <translation>%1: &apos;%2&apos; ist keine Zahl</translation>
    </message>
    <message>
        <source>%1 = %2 is outside %3 .. %4</source>
        <translation>%1 = %2 liegt außerhalb %3 .. %4</translation>
    </message>
    <message>
        <source>%1 must be a whole number</source>
        <translation>%1 muss eine ganze Zahl sein</translation>
    </message>
    <message>
        <source>no such value</source>
        <translation>diesen Wert gibt es nicht</translation>
    </message>
    <message>
        <source>FORM: write E or F (DIN 509)</source>
        <translation>FORM: E oder F schreiben (DIN 509)</translation>
    </message>
    <message>
        <source>contour number (the cycles machine it by this number)</source>
        <translation>Konturnummer (die Zyklen bearbeiten die Kontur unter dieser Nummer)</translation>
    </message>
    <message>
        <source>0 = final part contour, 1 = raw (blank) contour</source>
        <translation>0 = Fertigteilkontur, 1 = Rohteilkontur</translation>
    </message>
    <message>
        <source>the text to engrave</source>
        <translation>der zu gravierende Text</translation>
    </message>
    <message>
        <source>TEXT: 1 to 40 characters without &apos;&quot;&apos;</source>
        <translation>TEXT: 1 bis 40 Zeichen ohne &apos;&quot;&apos;</translation>
    </message>
    <message>
        <source>%1 (empty = %2)</source>
        <translation>%1 (leer = %2)</translation>
    </message>
    <message>
        <source>number of the contour or form to machine</source>
        <translation>Nummer der zu bearbeitenden Kontur oder Form</translation>
    </message>
    <message>
        <source>tool number</source>
        <translation>Werkzeugnummer</translation>
    </message>
    <message>
        <source>feed (mm/rev or mm/min as programmed)</source>
        <translation>Vorschub (mm/U oder mm/min wie programmiert)</translation>
    </message>
    <message>
        <source>spindle speed, 0 = leave unchanged</source>
        <translation>Spindeldrehzahl, 0 = unverändert</translation>
    </message>
    <message>
        <source>cutting edge orientation assumed (0..9)</source>
        <translation>angenommene Schneidenlage (0..9)</translation>
    </message>
    <message>
        <source>tool nose radius assumed</source>
        <translation>angenommener Schneidenradius</translation>
    </message>
    <message>
        <source>corner angle of the insert assumed (degrees)</source>
        <translation>angenommener Eckenwinkel der Wendeplatte (Grad)</translation>
    </message>
    <message>
        <source>setting angle of the tool assumed (degrees)</source>
        <translation>angenommener Einstellwinkel des Werkzeugs (Grad)</translation>
    </message>
    <message>
        <source>safety clearance for approach and retract</source>
        <translation>Sicherheitsabstand für An- und Abfahren</translation>
    </message>
    <message>
        <source>left end of the blank</source>
        <translation>linkes Ende des Rohteils</translation>
    </message>
    <message>
        <source>right end of the blank</source>
        <translation>rechtes Ende des Rohteils</translation>
    </message>
    <message>
        <source>outer radius of the blank</source>
        <translation>Außenradius des Rohteils</translation>
    </message>
    <message>
        <source>bore radius</source>
        <translation>Bohrungsradius</translation>
    </message>
    <message>
        <source>blank corner X</source>
        <translation>Rohteilecke X</translation>
    </message>
    <message>
        <source>blank corner Y</source>
        <translation>Rohteilecke Y</translation>
    </message>
    <message>
        <source>opposite corner X</source>
        <translation>gegenüberliegende Ecke X</translation>
    </message>
    <message>
        <source>opposite corner Y</source>
        <translation>gegenüberliegende Ecke Y</translation>
    </message>
    <message>
        <source>top face of the blank</source>
        <translation>Oberseite des Rohteils</translation>
    </message>
    <message>
        <source>bottom face of the blank</source>
        <translation>Unterseite des Rohteils</translation>
    </message>
    <message>
        <source>geometry number</source>
        <translation>Geometrienummer</translation>
    </message>
    <message>
        <source>right flank of the recess</source>
        <translation>rechte Flanke des Einstichs</translation>
    </message>
    <message>
        <source>radius the recess starts from</source>
        <translation>Radius, von dem der Einstich ausgeht</translation>
    </message>
    <message>
        <source>width of the recess</source>
        <translation>Breite des Einstichs</translation>
    </message>
    <message>
        <source>depth of the recess</source>
        <translation>Tiefe des Einstichs</translation>
    </message>
    <message>
        <source>centre of the 1st end</source>
        <translation>Mittelpunkt des 1. Endes</translation>
    </message>
    <message>
        <source>centre of the 2nd end</source>
        <translation>Mittelpunkt des 2. Endes</translation>
    </message>
    <message>
        <source>width of the hole</source>
        <translation>Breite des Langlochs</translation>
    </message>
    <message>
        <source>centre of the arc</source>
        <translation>Mittelpunkt des Bogens</translation>
    </message>
    <message>
        <source>radius of the middle line</source>
        <translation>Radius der Mittellinie</translation>
    </message>
    <message>
        <source>start angle (degrees)</source>
        <translation>Startwinkel (Grad)</translation>
    </message>
    <message>
        <source>end angle (degrees, counter-clockwise from A1)</source>
        <translation>Endwinkel (Grad, gegen den Uhrzeigersinn ab A1)</translation>
    </message>
    <message>
        <source>centre</source>
        <translation>Mittelpunkt</translation>
    </message>
    <message>
        <source>radius</source>
        <translation>Radius</translation>
    </message>
    <message>
        <source>radius of the circumscribed circle</source>
        <translation>Radius des Umkreises</translation>
    </message>
    <message>
        <source>number of corners</source>
        <translation>Anzahl der Ecken</translation>
    </message>
    <message>
        <source>angle of the first corner (degrees)</source>
        <translation>Winkel der ersten Ecke (Grad)</translation>
    </message>
    <message>
        <source>start of the base line</source>
        <translation>Anfang der Grundlinie</translation>
    </message>
    <message>
        <source>character height</source>
        <translation>Schrifthöhe</translation>
    </message>
    <message>
        <source>angle of the base line (degrees)</source>
        <translation>Winkel der Grundlinie (Grad)</translation>
    </message>
    <message>
        <source>centre of the base circle</source>
        <translation>Mittelpunkt des Grundkreises</translation>
    </message>
    <message>
        <source>radius of the base circle</source>
        <translation>Radius des Grundkreises</translation>
    </message>
    <message>
        <source>angle of the first character (degrees)</source>
        <translation>Winkel des ersten Zeichens (Grad)</translation>
    </message>
    <message>
        <source>corner</source>
        <translation>Ecke</translation>
    </message>
    <message>
        <source>opposite corner</source>
        <translation>gegenüberliegende Ecke</translation>
    </message>
    <message>
        <source>corner radius</source>
        <translation>Eckenradius</translation>
    </message>
    <message>
        <source>length along the angle</source>
        <translation>Länge in Winkelrichtung</translation>
    </message>
    <message>
        <source>width</source>
        <translation>Breite</translation>
    </message>
    <message>
        <source>angle of the length side (degrees)</source>
        <translation>Winkel der Längsseite (Grad)</translation>
    </message>
    <message>
        <source>depth of cut per pass (radius)</source>
        <translation>Zustellung je Schnitt (Radius)</translation>
    </message>
    <message>
        <source>allowance in X (radius)</source>
        <translation>Aufmaß in X (Radius)</translation>
    </message>
    <message>
        <source>allowance in Z</source>
        <translation>Aufmaß in Z</translation>
    </message>
    <message>
        <source>uniform allowance left for the contour cut</source>
        <translation>gleichmäßiges Aufmaß für den Konturschnitt</translation>
    </message>
    <message>
        <source>feed (mm/min)</source>
        <translation>Vorschub (mm/min)</translation>
    </message>
    <message>
        <source>tool radius assumed</source>
        <translation>angenommener Werkzeugradius</translation>
    </message>
    <message>
        <source>0 on the contour, 1 left (G41), 2 right (G42)</source>
        <translation>0 auf der Kontur, 1 links (G41), 2 rechts (G42)</translation>
    </message>
    <message>
        <source>safety plane</source>
        <translation>Sicherheitsebene</translation>
    </message>
    <message>
        <source>cutting depth (absolute Z)</source>
        <translation>Schnitttiefe (absolut Z)</translation>
    </message>
    <message>
        <source>plunge feed, 0 = F</source>
        <translation>Eintauchvorschub, 0 = F</translation>
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
    <name>MachineData</name>
    <message>
        <source>Adaptive feed control</source>
        <translation>Adaptive Vorschubregelung</translation>
    </message>
    <message>
        <source>Adapt. feed control active</source>
        <translation>Adapt. Vorschubregelung aktiv</translation>
    </message>
    <message>
        <source>Reference axis</source>
        <translation>Bezugsachse</translation>
    </message>
    <message>
        <source>Amplification</source>
        <translation>Verstärkung</translation>
    </message>
    <message>
        <source>Measuring period idling torque</source>
        <translation>Messdauer Leerlaufmoment</translation>
    </message>
    <message>
        <source>Current idling torque</source>
        <translation>Aktuelles Leerlaufmoment</translation>
    </message>
    <message>
        <source>Maximum idling torque</source>
        <translation>Maximales Leerlaufmoment</translation>
    </message>
    <message>
        <source>Current machining torque</source>
        <translation>Aktuelles Bearbeitungsmoment</translation>
    </message>
    <message>
        <source>Peak machining torque</source>
        <translation>Spitzenwert Bearbeitungsmoment</translation>
    </message>
    <message>
        <source>Minimum machining torque</source>
        <translation>Minimales Bearbeitungsmoment</translation>
    </message>
    <message>
        <source>Limiting machining torque</source>
        <translation>Grenzwert Bearbeitungsmoment</translation>
    </message>
    <message>
        <source>Current feed reduction</source>
        <translation>Aktuelle Vorschubreduzierung</translation>
    </message>
    <message>
        <source>Peak feed reduction</source>
        <translation>Spitzenwert Vorschubreduzierung</translation>
    </message>
    <message>
        <source>Maximum feed reduction</source>
        <translation>Maximale Vorschubreduzierung</translation>
    </message>
    <message>
        <source>Stall torque</source>
        <translation>Blockiermoment</translation>
    </message>
    <message>
        <source>NC program restart and REPOS</source>
        <translation>Satzvorlauf und Wiederanfahren (REPOS)</translation>
    </message>
    <message>
        <source>Rotary axis mode spindle %1</source>
        <translation>Rundachsbetrieb Spindel %1</translation>
    </message>
    <message>
        <source>Transformation selection</source>
        <translation>Transformationsanwahl</translation>
    </message>
    <message>
        <source>T no. tool spindle %1</source>
        <translation>T-Nr. Werkzeugspindel %1</translation>
    </message>
    <message>
        <source>M(16) and Q function buffers</source>
        <translation>Puffer der M(16)- und Q-Funktionen</translation>
    </message>
    <message>
        <source>M(16) functions</source>
        <translation>M(16)-Funktionen</translation>
    </message>
    <message>
        <source>Q functions</source>
        <translation>Q-Funktionen</translation>
    </message>
    <message>
        <source>Aux. Function %1</source>
        <translation>Hilfsfunktion %1</translation>
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
    <name>PanelStartup</name>
    <message>
        <source>cannot write %1: %2</source>
        <translation>%1 kann nicht geschrieben werden: %2</translation>
    </message>
    <message>
        <source>cannot read %1: %2</source>
        <translation>%1 kann nicht gelesen werden: %2</translation>
    </message>
    <message>
        <source>machine data is not kept</source>
        <translation>Maschinendaten werden nicht gespeichert</translation>
    </message>
    <message>
        <source>the machine configuration is refused:</source>
        <translation>die Maschinenkonfiguration wird abgewiesen:</translation>
    </message>
    <message>
        <source>is a file, not a program directory</source>
        <translation>ist eine Datei, kein Programmverzeichnis</translation>
    </message>
    <message>
        <source>does not exist</source>
        <translation>existiert nicht</translation>
    </message>
    <message>
        <source>the cell has no process %1</source>
        <translation>die Zelle hat keinen Prozess %1</translation>
    </message>
    <message>
        <source>no free program number for %1</source>
        <translation>keine freie Programmnummer für %1</translation>
    </message>
    <message>
        <source>station %1 has no program %2</source>
        <translation>Station %1 hat kein Programm %2</translation>
    </message>
    <message>
        <source>unknown screen &apos;%1&apos;</source>
        <translation>unbekannte Maske &apos;%1&apos;</translation>
    </message>
</context>
<context>
    <name>RestartCollisions</name>
    <message>
        <source>the part at the target could not be made</source>
        <translation>das Werkstück am Zielsatz konnte nicht gebildet werden</translation>
    </message>
    <message>
        <source>Way back not checked against the part: %1</source>
        <translation>Rückweg nicht gegen das Werkstück geprüft: %1</translation>
    </message>
    <message>
        <source>Way back clear: ADJUST/REPOS moves checked against the part: %1</source>
        <translation>Rückweg frei: gegen das Werkstück geprüfte ADJUST/REPOS-Bewegungen: %1</translation>
    </message>
    <message>
        <source>(line %1)</source>
        <translation>(Zeile %1)</translation>
    </message>
    <message>
        <source>%1 (machine)</source>
        <translation>%1 (Maschine)</translation>
    </message>
    <message>
        <source>ADJUST/REPOS moves that collide with the part: %1 of %2; the first: %3, %4 at %5. Check the way back before Start.</source>
        <translation>ADJUST/REPOS-Bewegungen mit Kollision am Werkstück: %1 von %2; die erste: %3, %4 bei %5. Rückweg vor Start prüfen.</translation>
    </message>
    <message>
        <source>rapid move touches the part</source>
        <translation>Eilgangbewegung berührt das Werkstück</translation>
    </message>
    <message>
        <source>feed move cuts the part</source>
        <translation>Vorschubbewegung schneidet das Werkstück</translation>
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
    <message>
        <source>0, Home</source>
        <translation>0, Pos1</translation>
    </message>
    <message>
        <source>frame the part: the cutting moves and the stock (F5 then frames every move, the rapids of an approach or tool change too)</source>
        <translation>das Werkstück einpassen: die Schnittbewegungen und das Rohteil (F5 passt dann alle Bewegungen ein, auch die Eilgänge einer Anfahrt oder eines Werkzeugwechsels)</translation>
    </message>
    <message>
        <source>the simulator&apos;s own layout</source>
        <translation>eigene Gestaltung des Simulators</translation>
    </message>
    <message>
        <source>M</source>
        <translation>M</translation>
    </message>
    <message>
        <source>hide or show the part: the stock cut by the whole program, or after Start the part as the tool has cut it so far</source>
        <translation>Werkstück aus- oder einblenden: das vom ganzen Programm bearbeitete Rohteil oder nach Start das Werkstück, so weit das Werkzeug es bearbeitet hat</translation>
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
        <translation>Fehler­fenster</translation>
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
        <translation>NC-­Optionen</translation>
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
    <name>mtc::hmi::NcOptionsHolder</name>
    <message>
        <source>there is no user compiler %1</source>
        <translation>es gibt keinen Anwender-Compiler %1</translation>
    </message>
    <message>
        <source>User compiler %1 not changed: %2</source>
        <translation>Anwender-Compiler %1 nicht geändert: %2</translation>
    </message>
    <message>
        <source>User compiler %1 not run: its command &apos;%2&apos; came with the program folder (%3) and was not approved</source>
        <translation>Anwender-Compiler %1 nicht ausgeführt: sein Befehl &apos;%2&apos; kam mit dem Programmordner (%3) und wurde nicht freigegeben</translation>
    </message>
    <message>
        <source>NC options not changed: station %1 is running a program</source>
        <translation>NC-Optionen nicht geändert: Station %1 führt ein Programm aus</translation>
    </message>
    <message>
        <source>NC options not changed, %1 not written: %2</source>
        <translation>NC-Optionen nicht geändert, %1 nicht geschrieben: %2</translation>
    </message>
    <message>
        <source>Macro refused: %1</source>
        <translation>Makro abgewiesen: %1</translation>
    </message>
    <message>
        <source>no global macro selected</source>
        <translation>kein globales Makro gewählt</translation>
    </message>
    <message>
        <source>Global macros not changed: station %1 is running a program</source>
        <translation>Globale Makros nicht geändert: Station %1 führt ein Programm aus</translation>
    </message>
    <message>
        <source>Global macros not changed, %1 not written: %2</source>
        <translation>Globale Makros nicht geändert, %1 nicht geschrieben: %2</translation>
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
    <name>mtc::hmi::ProgramWorkspace</name>
    <message>
        <source>compiled program, object line %1; source line %2</source>
        <translation>compiliertes Programm, Objektzeile %1; Quellzeile %2</translation>
    </message>
    <message>
        <source>unknown</source>
        <translation>unbekannt</translation>
    </message>
    <message>
        <source>program %1 does not exist</source>
        <translation>Programm %1 existiert nicht</translation>
    </message>
    <message>
        <source>the compiler is not active (NC options: Compiler active = No)</source>
        <translation>der Compiler ist nicht aktiv (NC-Optionen: Compiler aktiv = Nein)</translation>
    </message>
    <message>
        <source>the program uses no compiler keyword: nothing to compile</source>
        <translation>das Programm verwendet kein Compiler-Schlüsselwort: nichts zu compilieren</translation>
    </message>
    <message>
        <source>a user compiler runs: program %1 is compiled when it is done</source>
        <translation>ein Anwender-Compiler läuft: Programm %1 wird compiliert, wenn er fertig ist</translation>
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
    <name>mtc::screens::AfcTrendPlot</name>
    <message>
        <source>actual S-0-0084</source>
        <translation>Istwert S-0-0084</translation>
    </message>
    <message>
        <source>machining 007</source>
        <translation>Bearbeitung 007</translation>
    </message>
    <message>
        <source>limiting 010</source>
        <translation>Begrenzung 010</translation>
    </message>
    <message>
        <source>minimum 009</source>
        <translation>Minimum 009</translation>
    </message>
    <message>
        <source>idling 005</source>
        <translation>Leerlauf 005</translation>
    </message>
    <message>
        <source>max. idling 006</source>
        <translation>max. Leerlauf 006</translation>
    </message>
    <message>
        <source>stall 014</source>
        <translation>Blockierung 014</translation>
    </message>
    <message>
        <source>feed reduction 011</source>
        <translation>Vorschubreduzierung 011</translation>
    </message>
    <message>
        <source>peak 012</source>
        <translation>Spitze 012</translation>
    </message>
    <message>
        <source>maximum 013</source>
        <translation>Maximum 013</translation>
    </message>
    <message>
        <source>ITM measuring period</source>
        <translation>ITM-Messphase</translation>
    </message>
    <message>
        <source>torque %</source>
        <translation>Moment %</translation>
    </message>
    <message>
        <source>feed red. %</source>
        <translation>Vorschubred. %</translation>
    </message>
    <message>
        <source>no samples yet: run a program with G26 / ITM</source>
        <translation>noch keine Messwerte: ein Programm mit G26 / ITM ausführen</translation>
    </message>
    <message>
        <source>simulated time %1 s ... %2 s</source>
        <translation>simulierte Zeit %1 s ... %2 s</translation>
    </message>
</context>
<context>
    <name>mtc::screens::AfcTrendScreen</name>
    <message>
        <source>No trend yet (adaptive feed control records during feed moves).</source>
        <translation>Noch kein Verlauf (die adaptive Vorschubregelung zeichnet während Vorschubbewegungen auf).</translation>
    </message>
    <message>
        <source>t = %1 s   %2   actual %3 %   machining %4 %   reduction %5 % (peak %6 %)   feed %7 mm/min   idling 005 %8 % (max. 006 %9 %)   stall 014 %10 %   EXCTH %11   THMIS %12   samples %13</source>
        <translation>t = %1 s   %2   Ist %3 %   Bearbeitung %4 %   Reduzierung %5 % (Spitze %6 %)   Vorschub %7 mm/min   Leerlauf 005 %8 % (max. 006 %9 %)   Blockierung 014 %10 %   EXCTH %11   THMIS %12   Messwerte %13</translation>
    </message>
    <message>
        <source>G26 on</source>
        <translation>G26 ein</translation>
    </message>
    <message>
        <source>G26 off</source>
        <translation>G26 aus</translation>
    </message>
    <message>
        <source>Window: last %1 s</source>
        <translation>Fenster: letzte %1 s</translation>
    </message>
    <message>
        <source>Window: every sample kept</source>
        <translation>Fenster: alle Messwerte</translation>
    </message>
    <message>
        <source>PNG export failed: no image</source>
        <translation>PNG-Export fehlgeschlagen: kein Bild</translation>
    </message>
    <message>
        <source>PNG export failed: %1</source>
        <translation>PNG-Export fehlgeschlagen: %1</translation>
    </message>
    <message>
        <source>Trend written to %1</source>
        <translation>Verlauf geschrieben nach %1</translation>
    </message>
    <message>
        <source>CSV export failed: %1</source>
        <translation>CSV-Export fehlgeschlagen: %1</translation>
    </message>
    <message>
        <source>Window
10 s</source>
        <translation>Fenster
10 s</translation>
    </message>
    <message>
        <source>Window
60 s</source>
        <translation>Fenster
60 s</translation>
    </message>
    <message>
        <source>Window
all</source>
        <translation>Fenster
alles</translation>
    </message>
    <message>
        <source>Export
PNG</source>
        <translation>Export
PNG</translation>
    </message>
    <message>
        <source>Export
CSV</source>
        <translation>Export
CSV</translation>
    </message>
    <message>
        <source>Back</source>
        <translation>Zurück</translation>
    </message>
</context>
<context>
    <name>mtc::screens::EditorScreen</name>
    <message>
        <source>Program %1 has unsaved changes: Save (F1) or Discard (F7) first</source>
        <translation>Programm %1 hat ungespeicherte Änderungen: zuerst Speichern (F1) oder Verwerfen (F7)</translation>
    </message>
    <message>
        <source>Saved (program memory; built-in program without file)</source>
        <translation>Gespeichert (Programmspeicher; eingebautes Programm ohne Datei)</translation>
    </message>
    <message>
        <source>Saved to %1</source>
        <translation>Gespeichert in %1</translation>
    </message>
    <message>
        <source>Compiled: %1 object blocks, %2 warnings (Ctrl+E)</source>
        <translation>Compiliert: %1 Objektsätze, %2 Warnungen (Strg+E)</translation>
    </message>
    <message>
        <source>Compile error: %1 messages (Ctrl+E shows them)</source>
        <translation>Compilerfehler: %1 Meldungen (Strg+E zeigt sie)</translation>
    </message>
    <message>
        <source>The graphical NC editor (GNE) is not part of this panel yet</source>
        <translation>Der grafische NC-Editor (GNE) gehört noch nicht zu diesem Bedienfeld</translation>
    </message>
    <message>
        <source>Changes discarded, program reloaded</source>
        <translation>Änderungen verworfen, Programm neu geladen</translation>
    </message>
    <message>
        <source>(none)</source>
        <translation>(keines)</translation>
    </message>
    <message>
        <source>Program %1  %2  status [%3]%4</source>
        <translation>Programm %1  %2  Status [%3]%4</translation>
    </message>
    <message>
        <source>*modified*</source>
        <translation>*geändert*</translation>
    </message>
    <message>
        <source>Line %1 of %2   Block %3</source>
        <translation>Zeile %1 von %2   Satz %3</translation>
    </message>
    <message>
        <source>Save</source>
        <translation>Speichern</translation>
    </message>
    <message>
        <source>Compile</source>
        <translation>Compi­lieren</translation>
    </message>
    <message>
        <source>Errors
Ctrl+E</source>
        <translation>Fehler
Strg+E</translation>
    </message>
    <message>
        <source>GNE
Ctrl+W</source>
        <translation>GNE
Strg+W</translation>
    </message>
    <message>
        <source>GNE
(n/a)</source>
        <translation>GNE
(fehlt)</translation>
    </message>
    <message>
        <source>Runtime
program</source>
        <translation>Laufzeit­programm</translation>
    </message>
    <message>
        <source>Discard
changes</source>
        <translation>Ände­rungen
ver­werfen</translation>
    </message>
    <message>
        <source>Back</source>
        <translation>Zurück</translation>
    </message>
    <message>
        <source>The user compilers run; the status follows in the program directory</source>
        <translation>Die Anwender-Compiler laufen; der Status folgt im Programmverzeichnis</translation>
    </message>
    <message>
        <source>%1 lines opened</source>
        <translation>%1 Zeilen geöffnet</translation>
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
    <name>mtc::screens::GneCanvas</name>
    <message>
        <source>Z -&gt;   X ^   (turning, G18)</source>
        <translation>Z -&gt;   X ^   (Drehen, G18)</translation>
    </message>
    <message>
        <source>X -&gt;   Y ^   (milling, G17)</source>
        <translation>X -&gt;   Y ^   (Fräsen, G17)</translation>
    </message>
    <message>
        <source>zoom: window</source>
        <translation>Zoom: Fenster</translation>
    </message>
    <message>
        <source>zoom: contour</source>
        <translation>Zoom: Kontur</translation>
    </message>
    <message>
        <source>alternatives: %1</source>
        <translation>Alternativen: %1</translation>
    </message>
    <message>
        <source>solid: solved  dashed: open  dotted: other solution</source>
        <translation>durchgezogen: gelöst  gestrichelt: offen  gepunktet: andere Lösung</translation>
    </message>
</context>
<context>
    <name>mtc::screens::GneScreen</name>
    <message>
        <source>Save as function call (keywords with parameters)</source>
        <translation>Als Funktionsaufruf speichern (Schlüsselwörter mit Parametern)</translation>
    </message>
    <message>
        <source>Save as NC blocks (expanded)</source>
        <translation>Als NC-Sätze speichern (expandiert)</translation>
    </message>
    <message>
        <source>Discard the changes</source>
        <translation>Änderungen verwerfen</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Name</translation>
    </message>
    <message>
        <source>Value</source>
        <translation>Wert</translation>
    </message>
    <message>
        <source>Open the GNE from the program editor (GNE soft key on a line)</source>
        <translation>Den GNE aus dem Programm-Editor öffnen (Softkey GNE auf einer Zeile)</translation>
    </message>
    <message>
        <source>New GNE section before line %1</source>
        <translation>Neuer GNE-Abschnitt vor Zeile %1</translation>
    </message>
    <message>
        <source>Modifying the GNE section of lines %1-%2</source>
        <translation>GNE-Abschnitt der Zeilen %1-%2 wird geändert</translation>
    </message>
    <message>
        <source>GNE  program %1  %2%3</source>
        <translation>GNE  Programm %1  %2%3</translation>
    </message>
    <message>
        <source>new section at line %1</source>
        <translation>neuer Abschnitt an Zeile %1</translation>
    </message>
    <message>
        <source>lines %1-%2</source>
        <translation>Zeilen %1-%2</translation>
    </message>
    <message>
        <source>*modified*</source>
        <translation>*geändert*</translation>
    </message>
    <message>
        <source>Entry cancelled, value unchanged</source>
        <translation>Eingabe abgebrochen, Wert unverändert</translation>
    </message>
    <message>
        <source>Enter %1 (Enter takes it, Esc cancels, empty = not given)</source>
        <translation>%1 eingeben (Eingabe übernimmt, Esc bricht ab, leer = nicht angegeben)</translation>
    </message>
    <message>
        <source>%1 - the old value is kept</source>
        <translation>%1 - der alte Wert bleibt</translation>
    </message>
    <message>
        <source>Value taken</source>
        <translation>Wert übernommen</translation>
    </message>
    <message>
        <source>Value cleared: the solver computes it</source>
        <translation>Wert gelöscht: der Löser berechnet ihn</translation>
    </message>
    <message>
        <source>Insert after the selected row: Up/Down, Enter; Esc = back</source>
        <translation>Nach der gewählten Zeile einfügen: Auf/Ab, Eingabe; Esc = zurück</translation>
    </message>
    <message>
        <source>How shall the section go into the program? Up/Down, Enter; Esc = back</source>
        <translation>Wie soll der Abschnitt ins Programm? Auf/Ab, Eingabe; Esc = zurück</translation>
    </message>
    <message>
        <source>%1 inserted: enter its values (Enter)</source>
        <translation>%1 eingefügt: seine Werte eingeben (Eingabe)</translation>
    </message>
    <message>
        <source>Row deleted (Undo: F4 or Ctrl+Z)</source>
        <translation>Zeile gelöscht (Rückgängig: F4 oder Strg+Z)</translation>
    </message>
    <message>
        <source>The selected element has no other solution</source>
        <translation>Das gewählte Element hat keine andere Lösung</translation>
    </message>
    <message>
        <source>Solution %1 of %2 chosen</source>
        <translation>Lösung %1 von %2 gewählt</translation>
    </message>
    <message>
        <source>Undone</source>
        <translation>Rückgängig gemacht</translation>
    </message>
    <message>
        <source>Redone</source>
        <translation>Wiederhergestellt</translation>
    </message>
    <message>
        <source>No program: open the GNE from the editor</source>
        <translation>Kein Programm: den GNE aus dem Editor öffnen</translation>
    </message>
    <message>
        <source>Not saved - the section is not complete: %1</source>
        <translation>Nicht gespeichert - der Abschnitt ist nicht vollständig: %1</translation>
    </message>
    <message>
        <source>Insert
Ins</source>
        <translation>Einfügen
Einfg</translation>
    </message>
    <message>
        <source>Delete
row</source>
        <translation>Zeile
löschen</translation>
    </message>
    <message>
        <source>Alter-
native</source>
        <translation>Alter-
native</translation>
    </message>
    <message>
        <source>Undo</source>
        <translation>Rück­gängig</translation>
    </message>
    <message>
        <source>Redo</source>
        <translation>Wieder­herstellen</translation>
    </message>
    <message>
        <source>Zoom
contour</source>
        <translation>Zoom
Kontur</translation>
    </message>
    <message>
        <source>Zoom
window</source>
        <translation>Zoom
Fenster</translation>
    </message>
    <message>
        <source>Edit
value</source>
        <translation>Wert
bearbeiten</translation>
    </message>
    <message>
        <source>Exit</source>
        <translation>Ende</translation>
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
    <name>mtc::screens::MachineDataModel</name>
    <message>
        <source>Nr.</source>
        <translation>Nr.</translation>
    </message>
    <message>
        <source>Title</source>
        <translation>Titel</translation>
    </message>
    <message>
        <source>Value</source>
        <translation>Wert</translation>
    </message>
    <message>
        <source>Unit</source>
        <translation>Einheit</translation>
    </message>
</context>
<context>
    <name>mtc::screens::MachineDataScreen</name>
    <message>
        <source>Page %1  %2    process %3 (%4)</source>
        <translation>Seite %1  %2    Prozess %3 (%4)</translation>
    </message>
    <message>
        <source>sub %1: %2</source>
        <translation>Unterseite %1: %2</translation>
    </message>
    <message>
        <source>Page
-</source>
        <translation>Seite
-</translation>
    </message>
    <message>
        <source>Page
+</source>
        <translation>Seite
+</translation>
    </message>
    <message>
        <source>Edit</source>
        <translation>Bearbeiten</translation>
    </message>
    <message>
        <source>Back</source>
        <translation>Zurück</translation>
    </message>
    <message>
        <source>Element %1 is write-protected: only the NC changes it</source>
        <translation>Element %1 ist schreibgeschützt: nur die NC ändert es</translation>
    </message>
    <message>
        <source>New value of %1 (%2):</source>
        <translation>Neuer Wert von %1 (%2):</translation>
    </message>
    <message>
        <source>Input cancelled: the value stays %1</source>
        <translation>Eingabe abgebrochen: der Wert bleibt %1</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a number: %2 stays %3</source>
        <translation>&apos;%1&apos; ist keine Zahl: %2 bleibt %3</translation>
    </message>
    <message>
        <source>Wrong password: %1 stays %2</source>
        <translation>Falsches Passwort: %1 bleibt %2</translation>
    </message>
    <message>
        <source>Password for %1:</source>
        <translation>Passwort für %1:</translation>
    </message>
    <message>
        <source>%1: %2 stays %3</source>
        <translation>%1: %2 bleibt %3</translation>
    </message>
    <message>
        <source>NOT saved: %1</source>
        <translation>NICHT gespeichert: %1</translation>
    </message>
</context>
<context>
    <name>mtc::screens::MdiModel</name>
    <message>
        <source>MDI entry held: Start continues</source>
        <translation>MDI-Eingabe angehalten: Start setzt fort</translation>
    </message>
    <message>
        <source>MDI entry running</source>
        <translation>MDI-Eingabe läuft</translation>
    </message>
    <message>
        <source>MDI mode: Start runs the input</source>
        <translation>Betriebsart MDI: Start führt die Eingabe aus</translation>
    </message>
    <message>
        <source>%1 mode: Start does not run this input; select MDI mode with the M key MDI (Shift+F9)</source>
        <translation>Betriebsart %1: Start führt diese Eingabe nicht aus; Betriebsart MDI mit der M-Taste MDI (Umschalt+F9) wählen</translation>
    </message>
</context>
<context>
    <name>mtc::screens::MdiScreen</name>
    <message>
        <source>NC blocks, one a line (global macros allowed); Start runs them</source>
        <translation>NC-Sätze, einer je Zeile (globale Makros erlaubt); Start führt sie aus</translation>
    </message>
    <message>
        <source>Position (programmed)</source>
        <translation>Position (programmiert)</translation>
    </message>
    <message>
        <source>Modal state</source>
        <translation>Modaler Zustand</translation>
    </message>
    <message>
        <source>MDI input</source>
        <translation>MDI-Eingabe</translation>
    </message>
    <message>
        <source>Entries run</source>
        <translation>Ausgeführte Eingaben</translation>
    </message>
    <message>
        <source>Check
input</source>
        <translation>Eingabe
prüfen</translation>
    </message>
    <message>
        <source>Recall
entry</source>
        <translation>Eingabe
zurück­holen</translation>
    </message>
    <message>
        <source>Clear
input</source>
        <translation>Eingabe
löschen</translation>
    </message>
    <message>
        <source>Error
display</source>
        <translation>Fehler­fenster</translation>
    </message>
    <message>
        <source>Back</source>
        <translation>Zurück</translation>
    </message>
    <message>
        <source>Position (actual, running program)</source>
        <translation>Position (Istwert, laufendes Programm)</translation>
    </message>
    <message>
        <source>Modal state of the running block</source>
        <translation>Modaler Zustand des laufenden Satzes</translation>
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
    <name>mtc::screens::NcOptionsModel</name>
    <message>
        <source>Compiler active:          %1</source>
        <translation>Compiler aktiv:           %1</translation>
    </message>
    <message>
        <source>Yes</source>
        <translation>Ja</translation>
    </message>
    <message>
        <source>No</source>
        <translation>Nein</translation>
    </message>
    <message>
        <source>User compiler %1:        %2%3</source>
        <translation>Anwender-Compiler %1:    %2%3</translation>
    </message>
    <message>
        <source>[from the folder: asks before it runs]</source>
        <translation>[aus dem Ordner: fragt vor dem Ausführen]</translation>
    </message>
    <message>
        <source>INDRAMAT compiler:      %1</source>
        <translation>INDRAMAT-Compiler:      %1</translation>
    </message>
    <message>
        <source>active</source>
        <translation>aktiv</translation>
    </message>
    <message>
        <source>not active</source>
        <translation>nicht aktiv</translation>
    </message>
    <message>
        <source>Global macro  %1</source>
        <translation>Globales Makro  %1</translation>
    </message>
    <message>
        <source>Global macro  &lt;new&gt;</source>
        <translation>Globales Makro  &lt;neu&gt;</translation>
    </message>
    <message>
        <source>Syntax check:           in the controller at download</source>
        <translation>Syntaxprüfung:          in der Steuerung beim Download</translation>
    </message>
</context>
<context>
    <name>mtc::screens::NcOptionsScreen</name>
    <message>
        <source>kept in %1 (%2, %3)</source>
        <translation>gespeichert in %1 (%2, %3)</translation>
    </message>
    <message>
        <source>built-in programs: kept in memory until the panel ends</source>
        <translation>eingebaute Programme: im Speicher bis zum Ende des Bedienfelds</translation>
    </message>
    <message>
        <source>NC options of the cell, valid for every station and program — %1</source>
        <translation>NC-Optionen der Zelle, gültig für jede Station und jedes Programm — %1</translation>
    </message>
    <message>
        <source>Change</source>
        <translation>Ändern</translation>
    </message>
    <message>
        <source>Add
macro</source>
        <translation>Makro
hinzufügen</translation>
    </message>
    <message>
        <source>Delete
macro</source>
        <translation>Makro
löschen</translation>
    </message>
    <message>
        <source>Compiler
active: Yes</source>
        <translation>Compiler
aktiv: Ja</translation>
    </message>
    <message>
        <source>Compiler
active: No</source>
        <translation>Compiler
aktiv: Nein</translation>
    </message>
    <message>
        <source>Back</source>
        <translation>Zurück</translation>
    </message>
    <message>
        <source>The INDRAMAT compiler is switched with &quot;Compiler active&quot;.</source>
        <translation>Der INDRAMAT-Compiler wird mit „Compiler aktiv“ geschaltet.</translation>
    </message>
    <message>
        <source>Change the global macro:</source>
        <translation>Globales Makro ändern:</translation>
    </message>
    <message>
        <source>Compiler active = %1: the compile files of both stations are cleared</source>
        <translation>Compiler aktiv = %1: die Compilerdateien beider Stationen werden gelöscht</translation>
    </message>
    <message>
        <source>Yes</source>
        <translation>Ja</translation>
    </message>
    <message>
        <source>No</source>
        <translation>Nein</translation>
    </message>
    <message>
        <source>New global macro (DEFINE name AS instructions; name &lt;= 20 characters, instructions &lt;= 156):</source>
        <translation>Neues globales Makro (DEFINE Name AS Anweisungen; Name &lt;= 20 Zeichen, Anweisungen &lt;= 156):</translation>
    </message>
    <message>
        <source>Deleted: %1
Programs that used the global macros are set to N again.</source>
        <translation>Gelöscht: %1
Programme, die die globalen Makros benutzten, stehen wieder auf N.</translation>
    </message>
    <message>
        <source>Input cancelled: the NC options are unchanged</source>
        <translation>Eingabe abgebrochen: die NC-Optionen sind unverändert</translation>
    </message>
    <message>
        <source>User compiler %1 set: the compile files of both stations are cleared</source>
        <translation>Anwender-Compiler %1 gesetzt: die Compilerdateien beider Stationen werden gelöscht</translation>
    </message>
    <message>
        <source>Taken: %1
Programs that use the global macros are set to N again.</source>
        <translation>Übernommen: %1
Programme, die die globalen Makros benutzen, stehen wieder auf N.</translation>
    </message>
    <message>
        <source>Command of user compiler %1 (empty = none; called as COMMAND INPUT OUTPUT ERRORS):</source>
        <translation>Befehl des Anwender-Compilers %1 (leer = keiner; Aufruf als BEFEHL EINGABE AUSGABE FEHLER):</translation>
    </message>
    <message>
        <source>The syntax check is done by the controller at download; it has no setting.</source>
        <translation>Die Syntaxprüfung macht die Steuerung beim Download; sie hat keine Einstellung.</translation>
    </message>
</context>
<context>
    <name>mtc::screens::PainterToolpathCanvas</name>
    <message>
        <source>Developed plane (G32)</source>
        <translation>Abgewickelte Ebene (G32)</translation>
    </message>
    <message>
        <source>Toolpath (2D view, no OpenGL)</source>
        <translation>Bahn (2D-Ansicht, kein OpenGL)</translation>
    </message>
    <message>
        <source>extents %1 x %2 x %3 mm</source>
        <translation>Ausdehnung %1 x %2 x %3 mm</translation>
    </message>
    <message>
        <source>axial</source>
        <translation>axial</translation>
    </message>
    <message>
        <source>circ.</source>
        <translation>Umfang</translation>
    </message>
    <message>
        <source>axial (mm)</source>
        <translation>axial (mm)</translation>
    </message>
    <message>
        <source>circumferential (mm)</source>
        <translation>Umfang (mm)</translation>
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
<context>
    <name>mtc::screens::ProgramsScreen</name>
    <message>
        <source>Program %1 compiled: status %2, %3 messages</source>
        <translation>Programm %1 compiliert: Status %2, %3 Meldungen</translation>
    </message>
    <message>
        <source>NC options: Compiler active = %1</source>
        <translation>NC-Optionen: Compiler aktiv = %1</translation>
    </message>
    <message>
        <source>Yes</source>
        <translation>Ja</translation>
    </message>
    <message>
        <source>No</source>
        <translation>Nein</translation>
    </message>
    <message>
        <source>Select
program</source>
        <translation>Programm
anwählen</translation>
    </message>
    <message>
        <source>Edit</source>
        <translation>Bearbeiten</translation>
    </message>
    <message>
        <source>Compile</source>
        <translation>Compi­lieren</translation>
    </message>
    <message>
        <source>Runtime
program</source>
        <translation>Laufzeit­programm</translation>
    </message>
    <message>
        <source>NC
options</source>
        <translation>NC-
Optionen</translation>
    </message>
    <message>
        <source>Compiler
active: Yes</source>
        <translation>Compiler
aktiv: Ja</translation>
    </message>
    <message>
        <source>Compiler
active: No</source>
        <translation>Compiler
aktiv: Nein</translation>
    </message>
    <message>
        <source>Error
display</source>
        <translation>Fehler­fenster</translation>
    </message>
    <message>
        <source>Back</source>
        <translation>Zurück</translation>
    </message>
    <message>
        <source>Program %1: the user compilers run; the status follows</source>
        <translation>Programm %1: Die Anwender-Compiler laufen; der Status folgt</translation>
    </message>
</context>
<context>
    <name>mtc::screens::ReposModel</name>
    <message>
        <source>Axis</source>
        <translation>Achse</translation>
    </message>
    <message>
        <source>Actual position</source>
        <translation>Istposition</translation>
    </message>
    <message>
        <source>Re-entry point</source>
        <translation>Wiedereintrittspunkt</translation>
    </message>
    <message>
        <source>Distance</source>
        <translation>Abstand</translation>
    </message>
</context>
<context>
    <name>mtc::screens::ReposScreen</name>
    <message>
        <source>No NC program restart: the re-entry point is not known.</source>
        <translation>Kein Satzvorlauf: der Wiedereintrittspunkt ist nicht bekannt.</translation>
    </message>
    <message>
        <source>Jogged %1 by %2</source>
        <translation>%1 um %2 verfahren</translation>
    </message>
    <message>
        <source>Jogging is possible in manual mode between ADJUST and REPOS only (and within the travel range).</source>
        <translation>Verfahren ist nur im Handbetrieb zwischen ADJUST und REPOS möglich (und innerhalb des Verfahrbereichs).</translation>
    </message>
    <message>
        <source>Jog −</source>
        <translation>Tippen −</translation>
    </message>
    <message>
        <source>Jog +</source>
        <translation>Tippen +</translation>
    </message>
    <message>
        <source>Step
%1</source>
        <translation>Schritt
%1</translation>
    </message>
    <message>
        <source>Back</source>
        <translation>Zurück</translation>
    </message>
    <message>
        <source>Restart
result</source>
        <translation>Satzvorlauf
Ergebnis</translation>
    </message>
</context>
<context>
    <name>mtc::screens::RestartController</name>
    <message>
        <source>Verification refused: an NC program restart is active.</source>
        <translation>Prüfung abgewiesen: ein Satzvorlauf ist aktiv.</translation>
    </message>
    <message>
        <source>Verification refused: no program is displayed.</source>
        <translation>Prüfung abgewiesen: kein Programm angezeigt.</translation>
    </message>
    <message>
        <source>Verification refused: %1</source>
        <translation>Prüfung abgewiesen: %1</translation>
    </message>
    <message>
        <source>line %1</source>
        <translation>Zeile %1</translation>
    </message>
    <message>
        <source>No program is selected: select it in the program directory first.</source>
        <translation>Kein Programm angewählt: zuerst im Programmverzeichnis anwählen.</translation>
    </message>
    <message>
        <source>NC program restart needs automatic mode (seed 000, 2.1).</source>
        <translation>Der Satzvorlauf braucht die Betriebsart Automatik (Seed 000, 2.1).</translation>
    </message>
    <message>
        <source>A program is active: stop it with Control reset before the restart (seed 000, 2.1).</source>
        <translation>Ein Programm ist aktiv: vor dem Satzvorlauf mit Steuerung rücksetzen beenden (Seed 000, 2.1).</translation>
    </message>
    <message>
        <source>Select the target block and press Enter (Plane+ follows jumps and calls).</source>
        <translation>Zielsatz wählen und Eingabe drücken (Ebene+ folgt Sprüngen und Aufrufen).</translation>
    </message>
    <message>
        <source>Space changes the event, Enter follows the jump, Esc aborts.</source>
        <translation>Leertaste ändert das Ereignis, Eingabe folgt dem Sprung, Esc bricht ab.</translation>
    </message>
    <message>
        <source>Enter follows the jump with the value shown (or a new one), Esc aborts.</source>
        <translation>Eingabe folgt dem Sprung mit dem angezeigten (oder einem neuen) Wert, Esc bricht ab.</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a program number.</source>
        <translation>&apos;%1&apos; ist keine Programmnummer.</translation>
    </message>
    <message>
        <source>Aborted: the cursor stays where it was.</source>
        <translation>Abgebrochen: der Cursor bleibt, wo er war.</translation>
    </message>
    <message>
        <source>An NC program restart is already active: %1</source>
        <translation>Ein Satzvorlauf ist bereits aktiv: %1</translation>
    </message>
    <message>
        <source>Target accepted: %1</source>
        <translation>Ziel übernommen: %1</translation>
    </message>
    <message>
        <source>Target accepted. %1</source>
        <translation>Ziel übernommen. %1</translation>
    </message>
    <message>
        <source>P%1 %2 (line %3)</source>
        <translation>P%1 %2 (Zeile %3)</translation>
    </message>
    <message>
        <source>NC program restart active (PxxSBPACT = 1): the SPS starts the computing process.</source>
        <translation>Satzvorlauf aktiv (PxxSBPACT = 1): die SPS startet den Rechenlauf.</translation>
    </message>
    <message>
        <source>Computing process: %1 blocks interpreted. F7 or Control reset aborts.</source>
        <translation>Rechenlauf: %1 Sätze interpretiert. F7 oder Steuerung rücksetzen bricht ab.</translation>
    </message>
    <message>
        <source>Target block reached after %1 blocks (%2 ms). Check the result, then Start runs ADJUST.</source>
        <translation>Zielsatz nach %1 Sätzen erreicht (%2 ms). Ergebnis prüfen, dann führt Start ADJUST aus.</translation>
    </message>
    <message>
        <source>ADJUST establishes the machine states.</source>
        <translation>ADJUST stellt die Maschinenzustände her.</translation>
    </message>
    <message>
        <source>Manual mode: jog the axes near the re-entry point, then Automatic and Start.</source>
        <translation>Handbetrieb: Achsen in die Nähe des Wiedereintrittspunkts verfahren, dann Automatik und Start.</translation>
    </message>
    <message>
        <source>Automatic mode again: Start continues with REPOS.</source>
        <translation>Wieder Automatik: Start setzt mit REPOS fort.</translation>
    </message>
    <message>
        <source>REPOS moves the axes back to the re-entry point.</source>
        <translation>REPOS fährt die Achsen zum Wiedereintrittspunkt zurück.</translation>
    </message>
    <message>
        <source>State re-established: machining continues at the target block.</source>
        <translation>Zustand wiederhergestellt: die Bearbeitung läuft am Zielsatz weiter.</translation>
    </message>
    <message>
        <source>NC program restart failed.</source>
        <translation>Satzvorlauf fehlgeschlagen.</translation>
    </message>
    <message>
        <source>NC program restart aborted: every restart signal is reset.</source>
        <translation>Satzvorlauf abgebrochen: alle Satzvorlauf-Signale sind zurückgesetzt.</translation>
    </message>
    <message>
        <source>Waiting for another process: %1 (%2).</source>
        <translation>Wartet auf einen anderen Prozess: %1 (%2).</translation>
    </message>
    <message>
        <source>until it requests the axis with GAX</source>
        <translation>bis er die Achse mit GAX anfordert</translation>
    </message>
    <message>
        <source>until it relinquishes the axis with FAX</source>
        <translation>bis er die Achse mit FAX freigibt</translation>
    </message>
    <message>
        <source>Held: Start continues.</source>
        <translation>Angehalten: Start setzt fort.</translation>
    </message>
    <message>
        <source>Single block: held; Start interprets the next block (%1).</source>
        <translation>Einzelsatz: angehalten; Start interpretiert den nächsten Satz (%1).</translation>
    </message>
    <message>
        <source>No program</source>
        <translation>Kein Programm</translation>
    </message>
    <message>
        <source>Target P%1 %2 (line %3), program level %4</source>
        <translation>Ziel P%1 %2 (Zeile %3), Programmebene %4</translation>
    </message>
    <message>
        <source>start P%1 %2%3</source>
        <translation>Start P%1 %2%3</translation>
    </message>
    <message>
        <source>(last primary block)</source>
        <translation>(letzter Primärsatz)</translation>
    </message>
    <message>
        <source>start: no primary block before the target</source>
        <translation>Start: kein Primärsatz vor dem Ziel</translation>
    </message>
    <message>
        <source>event %1:%2=%3</source>
        <translation>Ereignis %1:%2=%3</translation>
    </message>
    <message>
        <source>changed %1</source>
        <translation>geändert %1</translation>
    </message>
    <message>
        <source>runs %1</source>
        <translation>Durchläufe %1</translation>
    </message>
</context>
<context>
    <name>mtc::screens::RestartResultModel</name>
    <message>
        <source>interpolation</source>
        <translation>Interpolation</translation>
    </message>
    <message>
        <source>plane</source>
        <translation>Ebene</translation>
    </message>
    <message>
        <source>tool path compensation</source>
        <translation>Bahnkorrektur</translation>
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
        <source>dimension</source>
        <translation>Maßangabe</translation>
    </message>
    <message>
        <source>radius / diameter</source>
        <translation>Radius / Durchmesser</translation>
    </message>
    <message>
        <source>units</source>
        <translation>Maßeinheit</translation>
    </message>
    <message>
        <source>surface speed</source>
        <translation>Schnittgeschwindigkeit</translation>
    </message>
    <message>
        <source>tool length compensation</source>
        <translation>Werkzeuglängenkorrektur</translation>
    </message>
    <message>
        <source>transformation</source>
        <translation>Transformation</translation>
    </message>
    <message>
        <source>none (−1)</source>
        <translation>keine (−1)</translation>
    </message>
    <message>
        <source>empty</source>
        <translation>leer</translation>
    </message>
    <message>
        <source>G functions (modal groups)</source>
        <translation>G-Funktionen (modale Gruppen)</translation>
    </message>
    <message>
        <source>G group %1 %2</source>
        <translation>G-Gruppe %1 %2</translation>
    </message>
    <message>
        <source>Auxiliary functions</source>
        <translation>Hilfsfunktionen</translation>
    </message>
    <message>
        <source>M group %1</source>
        <translation>M-Gruppe %1</translation>
    </message>
    <message>
        <source>M(16), last output</source>
        <translation>M(16), letzte Ausgabe</translation>
    </message>
    <message>
        <source>Q, last output</source>
        <translation>Q, letzte Ausgabe</translation>
    </message>
    <message>
        <source>S%1 speed</source>
        <translation>S%1 Drehzahl</translation>
    </message>
    <message>
        <source>T (tool)</source>
        <translation>T (Werkzeug)</translation>
    </message>
    <message>
        <source>D (correction)</source>
        <translation>D (Korrektur)</translation>
    </message>
    <message>
        <source>F (feed)</source>
        <translation>F (Vorschub)</translation>
    </message>
    <message>
        <source>Page 60 (restart and REPOS)</source>
        <translation>Seite 60 (Satzvorlauf und REPOS)</translation>
    </message>
    <message>
        <source>Rotary axis mode S%1</source>
        <translation>Rundachsbetrieb S%1</translation>
    </message>
    <message>
        <source>Transformation selection</source>
        <translation>Transformationsanwahl</translation>
    </message>
    <message>
        <source>T in tool spindle %1</source>
        <translation>T in Werkzeugspindel %1</translation>
    </message>
    <message>
        <source>Page 61 buffers, oldest first</source>
        <translation>Seite 61 Puffer, älteste zuerst</translation>
    </message>
    <message>
        <source>M(16) buffer</source>
        <translation>M(16)-Puffer</translation>
    </message>
    <message>
        <source>Q buffer</source>
        <translation>Q-Puffer</translation>
    </message>
    <message>
        <source>Verification: normal run vs. computing process, ADJUST and REPOS</source>
        <translation>Prüfung: normaler Lauf gegen Rechenlauf, ADJUST und REPOS</translation>
    </message>
    <message>
        <source>Not verified yet</source>
        <translation>Noch nicht geprüft</translation>
    </message>
    <message>
        <source>the restart fails</source>
        <translation>der Satzvorlauf scheitert</translation>
    </message>
    <message>
        <source>Verification</source>
        <translation>Prüfung</translation>
    </message>
    <message>
        <source>Every item</source>
        <translation>Jeder Eintrag</translation>
    </message>
    <message>
        <source>re-established</source>
        <translation>wiederhergestellt</translation>
    </message>
    <message>
        <source>Computing process: %1</source>
        <translation>Rechenlauf: %1</translation>
    </message>
    <message>
        <source>After ADJUST / REPOS: %1</source>
        <translation>Nach ADJUST / REPOS: %1</translation>
    </message>
    <message>
        <source>not verified yet</source>
        <translation>noch nicht geprüft</translation>
    </message>
    <message>
        <source>%1 differences</source>
        <translation>%1 Unterschiede</translation>
    </message>
    <message>
        <source>Item</source>
        <translation>Eintrag</translation>
    </message>
    <message>
        <source>At the target</source>
        <translation>Am Ziel</translation>
    </message>
    <message>
        <source>Machine before</source>
        <translation>Maschine vorher</translation>
    </message>
    <message>
        <source>Way back against the part (ADJUST / REPOS)</source>
        <translation>Rückweg gegen das Werkstück (ADJUST / REPOS)</translation>
    </message>
</context>
<context>
    <name>mtc::screens::RestartResultScreen</name>
    <message>
        <source>No computing process yet: select the target on the restart screen.</source>
        <translation>Noch kein Rechenlauf: das Ziel in der Satzvorlauf-Maske wählen.</translation>
    </message>
    <message>
        <source>Target %1  ·  %2 blocks interpreted  ·  %3 differences  ·  verification: %4</source>
        <translation>Ziel %1  ·  %2 Sätze interpretiert  ·  %3 Unterschiede  ·  Prüfung: %4</translation>
    </message>
    <message>
        <source>  ·  arrival %1</source>
        <translation>  ·  Ankunft %1</translation>
    </message>
    <message>
        <source>All
items</source>
        <translation>Alle
Einträge</translation>
    </message>
    <message>
        <source>Differences
only</source>
        <translation>Nur Unter­schiede</translation>
    </message>
    <message>
        <source>Verify
target</source>
        <translation>Ziel
prüfen</translation>
    </message>
    <message>
        <source>Back</source>
        <translation>Zurück</translation>
    </message>
    <message>
        <source>Reposition</source>
        <translation>Wieder­anfahren</translation>
    </message>
    <message>
        <source>Target
selection</source>
        <translation>Ziel
wählen</translation>
    </message>
</context>
<context>
    <name>mtc::screens::RestartScreen</name>
    <message>
        <source>1  (set)</source>
        <translation>1  (gesetzt)</translation>
    </message>
    <message>
        <source>0  (not set)</source>
        <translation>0  (nicht gesetzt)</translation>
    </message>
    <message>
        <source>Plane +</source>
        <translation>Ebene +</translation>
    </message>
    <message>
        <source>Plane −</source>
        <translation>Ebene −</translation>
    </message>
    <message>
        <source>Search
string</source>
        <translation>Such­begriff</translation>
    </message>
    <message>
        <source>From last
primary ✓</source>
        <translation>Ab letztem
Primärsatz ✓</translation>
    </message>
    <message>
        <source>From last
primary block</source>
        <translation>Ab letztem
Primärsatz</translation>
    </message>
    <message>
        <source>Number
of runs</source>
        <translation>Anzahl
Durchläufe</translation>
    </message>
    <message>
        <source>Accept
target</source>
        <translation>Ziel
über­nehmen</translation>
    </message>
    <message>
        <source>Abort</source>
        <translation>Abbruch</translation>
    </message>
    <message>
        <source>Verify
program</source>
        <translation>Programm
prüfen</translation>
    </message>
    <message>
        <source>Back</source>
        <translation>Zurück</translation>
    </message>
    <message>
        <source>Search string:</source>
        <translation>Suchbegriff:</translation>
    </message>
    <message>
        <source>Enter: next occurrence towards the end · Esc: close</source>
        <translation>Eingabe: nächste Fundstelle zum Ende hin · Esc: schließen</translation>
    </message>
    <message>
        <source>Number of runs (1 … 65536):</source>
        <translation>Anzahl Durchläufe (1 … 65536):</translation>
    </message>
    <message>
        <source>Enter: set · Esc: keep the old value</source>
        <translation>Eingabe: setzen · Esc: alten Wert behalten</translation>
    </message>
    <message>
        <source>%1: event %2:%3</source>
        <translation>%1: Ereignis %2:%3</translation>
    </message>
    <message>
        <source>Space: change · Enter: follow the jump · Esc: abort</source>
        <translation>Leertaste: ändern · Eingabe: dem Sprung folgen · Esc: abbrechen</translation>
    </message>
    <message>
        <source>%1 %2 = program number:</source>
        <translation>%1 %2 = Programmnummer:</translation>
    </message>
    <message>
        <source>Enter: jump with this value · Esc: abort</source>
        <translation>Eingabe: mit diesem Wert springen · Esc: abbrechen</translation>
    </message>
    <message>
        <source>read only (other process) · Enter: jump · Esc: abort</source>
        <translation>nur lesbar (anderer Prozess) · Eingabe: springen · Esc: abbrechen</translation>
    </message>
</context>
<context>
    <name>mtc::screens::RestartVerification</name>
    <message>
        <source>program %1 cannot be verified</source>
        <translation>Programm %1 kann nicht geprüft werden</translation>
    </message>
    <message>
        <source>Verifying P%1: %2 arrivals checked …</source>
        <translation>Prüfe P%1: %2 Ankünfte geprüft …</translation>
    </message>
    <message>
        <source>Verification of P%1: %2</source>
        <translation>Prüfung von P%1: %2</translation>
    </message>
</context>
<context>
    <name>mtc::screens::RuntimeScreen</name>
    <message>
        <source>Program %1  %2   source  |  runtime program   status [%3]</source>
        <translation>Programm %1  %2   Quelle  |  Laufzeitprogramm   Status [%3]</translation>
    </message>
    <message>
        <source>(none)</source>
        <translation>(keines)</translation>
    </message>
    <message>
        <source>%1 marks the blocks tool compensation inserts while the program runs.</source>
        <translation>%1 markiert die Sätze, die die Werkzeugkorrektur beim Programmlauf einfügt.</translation>
    </message>
    <message>
        <source>%1 blocks inserted by the compiler (N....:0001, ...).</source>
        <translation>%1 Sätze vom Compiler eingefügt (N....:0001, ...).</translation>
    </message>
    <message>
        <source>The program needs no compilation: it runs as written.</source>
        <translation>Das Programm braucht keine Compilierung: es läuft, wie es geschrieben ist.</translation>
    </message>
    <message>
        <source>The program has compile errors (error display: Ctrl+E in the editor).</source>
        <translation>Das Programm hat Compilerfehler (Fehlerfenster: Strg+E im Editor).</translation>
    </message>
    <message>
        <source>The program is not compiled yet (Compile in the editor or the program directory).</source>
        <translation>Das Programm ist noch nicht compiliert (Compilieren im Editor oder im Programmverzeichnis).</translation>
    </message>
    <message>
        <source>No look-ahead segment (LA_ON ... LA_OFF) in the last compile</source>
        <translation>Kein Look-ahead-Abschnitt (LA_ON ... LA_OFF) in der letzten Compilierung</translation>
    </message>
    <message>
        <source>LA segment %1 of %2 (line %3): %4 blocks</source>
        <translation>LA-Abschnitt %1 von %2 (Zeile %3): %4 Sätze</translation>
    </message>
    <message>
        <source>Compile</source>
        <translation>Compi­lieren</translation>
    </message>
    <message>
        <source>Next LA
segment</source>
        <translation>Nächster
LA-­Abschnitt</translation>
    </message>
    <message>
        <source>Editor</source>
        <translation>Editor</translation>
    </message>
    <message>
        <source>Back</source>
        <translation>Zurück</translation>
    </message>
</context>
<context>
    <name>mtc::screens::SetupTableScreen</name>
    <message>
        <source>Refused: %1</source>
        <translation>Abgewiesen: %1</translation>
    </message>
    <message>
        <source>(effective from the next block)</source>
        <translation>(wirksam ab dem nächsten Satz)</translation>
    </message>
    <message>
        <source>Not kept in a file: the panel runs without a machine data file</source>
        <translation>Nicht in einer Datei gespeichert: das Bedienfeld läuft ohne Maschinendatendatei</translation>
    </message>
</context>
<context>
    <name>mtc::screens::SignalModel</name>
    <message>
        <source>Signal</source>
        <translation>Signal</translation>
    </message>
    <message>
        <source>Value</source>
        <translation>Wert</translation>
    </message>
    <message>
        <source>Step</source>
        <translation>Schritt</translation>
    </message>
</context>
<context>
    <name>mtc::screens::SignalsScreen</name>
    <message>
        <source>Clear
log</source>
        <translation>Protokoll
löschen</translation>
    </message>
    <message>
        <source>Back</source>
        <translation>Zurück</translation>
    </message>
</context>
<context>
    <name>mtc::screens::ToolTableModel</name>
    <message>
        <source>T</source>
        <translation>T</translation>
    </message>
    <message>
        <source>tool number</source>
        <translation>Werkzeugnummer</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Name</translation>
    </message>
    <message>
        <source>name</source>
        <translation>Name</translation>
    </message>
    <message>
        <source>E</source>
        <translation>E</translation>
    </message>
    <message>
        <source>cutting edge</source>
        <translation>Schneide</translation>
    </message>
    <message>
        <source>R</source>
        <translation>R</translation>
    </message>
    <message>
        <source>radius R</source>
        <translation>Radius R</translation>
    </message>
    <message>
        <source>R
wear</source>
        <translation>R
Verschl.</translation>
    </message>
    <message>
        <source>wear of R</source>
        <translation>Verschleiß von R</translation>
    </message>
    <message>
        <source>L1</source>
        <translation>L1</translation>
    </message>
    <message>
        <source>length L1</source>
        <translation>Länge L1</translation>
    </message>
    <message>
        <source>L1
wear</source>
        <translation>L1
Verschl.</translation>
    </message>
    <message>
        <source>wear of L1</source>
        <translation>Verschleiß von L1</translation>
    </message>
    <message>
        <source>L2</source>
        <translation>L2</translation>
    </message>
    <message>
        <source>length L2</source>
        <translation>Länge L2</translation>
    </message>
    <message>
        <source>L2
wear</source>
        <translation>L2
Verschl.</translation>
    </message>
    <message>
        <source>wear of L2</source>
        <translation>Verschleiß von L2</translation>
    </message>
    <message>
        <source>L3</source>
        <translation>L3</translation>
    </message>
    <message>
        <source>length L3</source>
        <translation>Länge L3</translation>
    </message>
    <message>
        <source>L3
wear</source>
        <translation>L3
Verschl.</translation>
    </message>
    <message>
        <source>wear of L3</source>
        <translation>Verschleiß von L3</translation>
    </message>
    <message>
        <source>Pos</source>
        <translation>Lage</translation>
    </message>
    <message>
        <source>cutting edge position</source>
        <translation>Schneidenlage</translation>
    </message>
    <message>
        <source>Corner</source>
        <translation>Ecke</translation>
    </message>
    <message>
        <source>corner angle</source>
        <translation>Eckenwinkel</translation>
    </message>
    <message>
        <source>Setting</source>
        <translation>Einstell.</translation>
    </message>
    <message>
        <source>setting angle</source>
        <translation>Einstellwinkel</translation>
    </message>
</context>
<context>
    <name>mtc::screens::ToolTableScreen</name>
    <message>
        <source>Tool list of process %1 (%2): %3 edges
File: %4</source>
        <translation>Werkzeugliste von Prozess %1 (%2): %3 Schneiden
Datei: %4</translation>
    </message>
    <message>
        <source>none, changes hold until the panel ends</source>
        <translation>keine, Änderungen gelten bis zum Ende des Bedienfelds</translation>
    </message>
    <message>
        <source>Edit</source>
        <translation>Bearbeiten</translation>
    </message>
    <message>
        <source>New tool</source>
        <translation>Neues Werkzeug</translation>
    </message>
    <message>
        <source>New edge</source>
        <translation>Neue Schneide</translation>
    </message>
    <message>
        <source>Delete edge</source>
        <translation>Schneide löschen</translation>
    </message>
    <message>
        <source>Delete tool</source>
        <translation>Werkzeug löschen</translation>
    </message>
    <message>
        <source>Back</source>
        <translation>Zurück</translation>
    </message>
    <message>
        <source>The tool list is empty: F2 adds a tool</source>
        <translation>Die Werkzeugliste ist leer: F2 fügt ein Werkzeug hinzu</translation>
    </message>
    <message>
        <source>The tool and edge numbers are not edited: F2 adds a tool, F3 an edge</source>
        <translation>Werkzeug- und Schneidennummern werden nicht bearbeitet: F2 fügt ein Werkzeug hinzu, F3 eine Schneide</translation>
    </message>
    <message>
        <source>New %1 of %2 (%3):</source>
        <translation>Neuer Wert %1 von %2 (%3):</translation>
    </message>
    <message>
        <source>Number of the new tool (1 .. %1):</source>
        <translation>Nummer des neuen Werkzeugs (1 .. %1):</translation>
    </message>
    <message>
        <source>New cutting edge of T%1 (1 .. %2):</source>
        <translation>Neue Schneide von T%1 (1 .. %2):</translation>
    </message>
    <message>
        <source>tool T%1 with all its edges</source>
        <translation>Werkzeug T%1 mit allen Schneiden</translation>
    </message>
    <message>
        <source>edge %1</source>
        <translation>Schneide %1</translation>
    </message>
    <message>
        <source>Delete %1? Enter deletes, Esc keeps it:</source>
        <translation>%1 löschen? Eingabe löscht, Esc behält:</translation>
    </message>
    <message>
        <source>Input cancelled: %1 %2 stays %3</source>
        <translation>Eingabe abgebrochen: %1 %2 bleibt %3</translation>
    </message>
    <message>
        <source>Cancelled: the tool list is unchanged</source>
        <translation>Abgebrochen: die Werkzeugliste ist unverändert</translation>
    </message>
    <message>
        <source>%1 stays %2</source>
        <translation>%1 bleibt %2</translation>
    </message>
    <message>
        <source>New tool %1: enter its values</source>
        <translation>Neues Werkzeug %1: seine Werte eingeben</translation>
    </message>
    <message>
        <source>No tool was added</source>
        <translation>Kein Werkzeug hinzugefügt</translation>
    </message>
    <message>
        <source>New edge %1: enter its values</source>
        <translation>Neue Schneide %1: ihre Werte eingeben</translation>
    </message>
    <message>
        <source>No edge was added</source>
        <translation>Keine Schneide hinzugefügt</translation>
    </message>
    <message>
        <source>%1 deleted</source>
        <translation>%1 gelöscht</translation>
    </message>
    <message>
        <source>%1 is kept</source>
        <translation>%1 bleibt erhalten</translation>
    </message>
</context>
<context>
    <name>mtc::screens::ToolpathModel</name>
    <message>
        <source>Program %1 does not exist.</source>
        <translation>Programm %1 existiert nicht.</translation>
    </message>
    <message>
        <source>No program is selected: select one in the program directory.</source>
        <translation>Kein Programm angewählt: eines im Programmverzeichnis anwählen.</translation>
    </message>
    <message>
        <source>%1 moves · %2 segments · tolerance %3 mm</source>
        <translation>%1 Bewegungen · %2 Segmente · Toleranz %3 mm</translation>
    </message>
    <message>
        <source>G32 RI %1: developed plane | cylinder</source>
        <translation>G32 RI %1: abgewickelte Ebene | Zylinder</translation>
    </message>
    <message>
        <source>path cut at the segment limit</source>
        <translation>Bahn an der Segmentgrenze abgeschnitten</translation>
    </message>
    <message>
        <source>program end not reached</source>
        <translation>Programmende nicht erreicht</translation>
    </message>
    <message>
        <source>editor</source>
        <translation>Editor</translation>
    </message>
    <message>
        <source>restart</source>
        <translation>Satzvorlauf</translation>
    </message>
    <message>
        <source>P%1 %2 (line %3)</source>
        <translation>P%1 %2 (Zeile %3)</translation>
    </message>
    <message>
        <source>Machine coordinates (G53, no zero offset)</source>
        <translation>Maschinenkoordinaten (G53, keine Nullpunktverschiebung)</translation>
    </message>
    <message>
        <source>Workpiece coordinates G%1,
zero point at machine %2</source>
        <translation>Werkstückkoordinaten G%1,
Nullpunkt bei Maschine %2</translation>
    </message>
    <message>
        <source>Finished part not simulated (over %1 blocks): key M</source>
        <translation>Fertigteil nicht simuliert (über %1 Sätze): Taste M</translation>
    </message>
    <message>
        <source>no stock</source>
        <translation>kein Rohteil</translation>
    </message>
    <message>
        <source>No finished part: %1</source>
        <translation>Kein Fertigteil: %1</translation>
    </message>
    <message>
        <source>Finished part: the program removes nothing from the stock</source>
        <translation>Fertigteil: Das Programm trägt vom Rohteil nichts ab</translation>
    </message>
    <message>
        <source>Finished part: %1 mm³ removed at %2 mm</source>
        <translation>Fertigteil: %1 mm³ abgetragen bei %2 mm</translation>
    </message>
    <message>
        <source>%1 (mm, radius, G%2)</source>
        <translation>%1 (mm, Radius, G%2)</translation>
    </message>
    <message>
        <source>Part being cut: %1 mm³ removed at %2 mm</source>
        <translation>Werkstück in Bearbeitung: %1 mm³ abgetragen bei %2 mm</translation>
    </message>
    <message>
        <source>Part as the run left it: %1 mm³ removed at %2 mm</source>
        <translation>Werkstück nach dem Lauf: %1 mm³ abgetragen bei %2 mm</translation>
    </message>
    <message>
        <source>Part from the restart&apos;s target block on: %1 mm³ removed at %2 mm</source>
        <translation>Werkstück ab dem Zielsatz des Wiederanlaufs: %1 mm³ abgetragen bei %2 mm</translation>
    </message>
    <message>
        <source>Part of the run, cut on by MDI and jogging: %1 mm³ removed at %2 mm</source>
        <translation>Werkstück des Laufs, mit MDI und Handverfahren weiter bearbeitet: %1 mm³ abgetragen bei %2 mm</translation>
    </message>
</context>
<context>
    <name>mtc::screens::ToolpathScreen</name>
    <message>
        <source>MTC_TOOLPATH_2D is set</source>
        <translation>MTC_TOOLPATH_2D ist gesetzt</translation>
    </message>
    <message>
        <source>the Qt platform &apos;%1&apos; has no OpenGL</source>
        <translation>die Qt-Plattform &apos;%1&apos; hat kein OpenGL</translation>
    </message>
    <message>
        <source>no OpenGL context can be created</source>
        <translation>kein OpenGL-Kontext kann erzeugt werden</translation>
    </message>
    <message>
        <source>the OpenGL context cannot be made current</source>
        <translation>der OpenGL-Kontext kann nicht aktiviert werden</translation>
    </message>
    <message>
        <source>2D view: %1 (the 3D view needs OpenGL).</source>
        <translation>2D-Ansicht: %1 (die 3D-Ansicht braucht OpenGL).</translation>
    </message>
    <message>
        <source>Tool centre path:</source>
        <translation>Werkzeugmittelpunktsbahn:</translation>
    </message>
    <message>
        <source>programmed contour (G41/G42, edge, G48)</source>
        <translation>programmierte Kontur (G41/G42, Schneide, G48)</translation>
    </message>
    <message>
        <source>Linked to the %1</source>
        <translation>Verknüpft mit: %1</translation>
    </message>
    <message>
        <source>highlighted: %1</source>
        <translation>hervorgehoben: %1</translation>
    </message>
    <message>
        <source>2D view: %1</source>
        <translation>2D-Ansicht: %1</translation>
    </message>
    <message>
        <source>View %1</source>
        <translation>Ansicht %1</translation>
    </message>
    <message>
        <source>isometric</source>
        <translation>isometrisch</translation>
    </message>
    <message>
        <source>The view could not be turned into a PNG picture.</source>
        <translation>Die Ansicht konnte nicht in ein PNG-Bild umgewandelt werden.</translation>
    </message>
    <message>
        <source>PNG not written: %1</source>
        <translation>PNG nicht geschrieben: %1</translation>
    </message>
    <message>
        <source>View written to %1</source>
        <translation>Ansicht geschrieben nach %1</translation>
    </message>
    <message>
        <source>G17
view</source>
        <translation>G17-
Ansicht</translation>
    </message>
    <message>
        <source>G18
view</source>
        <translation>G18-
Ansicht</translation>
    </message>
    <message>
        <source>G19
view</source>
        <translation>G19-
Ansicht</translation>
    </message>
    <message>
        <source>Iso-
metric</source>
        <translation>Iso-
metrisch</translation>
    </message>
    <message>
        <source>Export
PNG</source>
        <translation>Export
PNG</translation>
    </message>
    <message>
        <source>Back</source>
        <translation>Zurück</translation>
    </message>
    <message>
        <source>Restart</source>
        <translation>Satzvorlauf</translation>
    </message>
    <message>
        <source>Every move framed, rapids included (F5: the part again).</source>
        <translation>Alle Bewegungen eingepasst, Eilgänge eingeschlossen (F5: wieder das Werkstück).</translation>
    </message>
    <message>
        <source>The part framed: cutting moves and stock (F5: every move).</source>
        <translation>Werkstück eingepasst: Schnittbewegungen und Rohteil (F5: alle Bewegungen).</translation>
    </message>
    <message>
        <source>Fit
part</source>
        <translation>Werkstück
einpassen</translation>
    </message>
    <message>
        <source>Fit
all</source>
        <translation>Alles
einpassen</translation>
    </message>
    <message>
        <source>running: %1</source>
        <translation>läuft: %1</translation>
    </message>
    <message>
        <source>travelled since Start</source>
        <translation>seit Start verfahren</translation>
    </message>
    <message>
        <source>(M hides)</source>
        <translation>(M blendet aus)</translation>
    </message>
</context>
<context>
    <name>mtc::screens::VelocityPlot</name>
    <message>
        <source>path %1 mm, %2 s</source>
        <translation>Weg %1 mm, %2 s</translation>
    </message>
</context>
<context>
    <name>mtc::screens::VtkToolpathCanvas</name>
    <message>
        <source>extents %1 x %2</source>
        <translation>Ausdehnung %1 x %2</translation>
    </message>
    <message>
        <source>axial (mm)</source>
        <translation>axial (mm)</translation>
    </message>
    <message>
        <source>circumference (mm)</source>
        <translation>Umfang (mm)</translation>
    </message>
    <message>
        <source>Developed plane, G32 RI %1</source>
        <translation>Abgewickelte Ebene, G32 RI %1</translation>
    </message>
    <message>
        <source>Wrapped on the cylinder RI %1</source>
        <translation>Auf den Zylinder RI %1 gewickelt</translation>
    </message>
    <message>
        <source>Toolpath P%1</source>
        <translation>Bahn P%1</translation>
    </message>
</context>
<context>
    <name>mtc::screens::ZeroOffsetModel</name>
    <message>
        <source>Offset</source>
        <translation>Verschiebung</translation>
    </message>
</context>
<context>
    <name>mtc::screens::ZeroOffsetScreen</name>
    <message>
        <source>Zero offsets of process %1 (%2). Columns are axis definitions (axis: definitions %3)
File: %4</source>
        <translation>Nullpunktverschiebungen von Prozess %1 (%2). Spalten sind Achsdefinitionen (Achse: Definitionen %3)
Datei: %4</translation>
    </message>
    <message>
        <source>none, changes hold until the panel ends</source>
        <translation>keine, Änderungen gelten bis zum Ende des Bedienfelds</translation>
    </message>
    <message>
        <source>Edit</source>
        <translation>Bearbeiten</translation>
    </message>
    <message>
        <source>Back</source>
        <translation>Zurück</translation>
    </message>
    <message>
        <source>Put the cursor on an axis column (cursor right) to change an offset</source>
        <translation>Cursor auf eine Achsspalte setzen (Cursor rechts), um eine Verschiebung zu ändern</translation>
    </message>
    <message>
        <source>New zero offset %1 (-%2 .. %2 mm, degrees on a rotary axis):</source>
        <translation>Neue Nullpunktverschiebung %1 (-%2 .. %2 mm, Grad bei einer Rundachse):</translation>
    </message>
    <message>
        <source>%1 stays %2</source>
        <translation>%1 bleibt %2</translation>
    </message>
    <message>
        <source>Input cancelled: %1 stays %2</source>
        <translation>Eingabe abgebrochen: %1 bleibt %2</translation>
    </message>
</context>
</TS>

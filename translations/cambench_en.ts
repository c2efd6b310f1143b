<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="en_US">
<context>
    <name>CamDiagramWidget</name>
    <message>
        <source>Output %1, cam %2: on %3, off %4, length %5</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Changed, not yet written to the device.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1  %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Output</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>CamDocument</name>
    <message>
        <source>Change cam on output %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Add cam to output %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Delete cam of output %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Copy output %1 to output %2 of program %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Copy program %1 to program %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Generate cams on output %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Rename program %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Rename output %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Change dead time of output %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>CamEditorWidget</name>
    <message>
        <source>&amp;Undo</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Redo</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Read Program</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Read the current program from the device</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Write Program</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Write the current program to the device</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Add Cam</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Add a cam to the selected output</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Delete Cam</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Delete the selected cam</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Copy &amp;Output To…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Copy the cams of the selected output to another output</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Copy &amp;Program To…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Copy the whole program to another program number</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Generate Cams…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Replace the cams of the selected output by evenly spaced cams</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Import CSV…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Replace the cams of this program from a CSV file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Export CSV…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save the cams of this program as a CSV file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Zoom &amp;In</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Show a smaller part of the axis</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Zoom &amp;Out</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Show a larger part of the axis</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Fit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Show the whole axis IMIN..IMAX</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no name</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Program:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Name:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cams of output %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cams of output %1 (%2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Program Name</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Copy Output</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Copy the cams of output %1 to output (its cams are replaced):</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Copy Program</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Copy program %1 to program (its cams and name are replaced):</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: output %2 does not exist; the device has outputs 1..%3. Nothing was imported.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Import cams from %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Import Cams</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CSV files (*.csv);;All files (*)</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>The cams were imported, but %n need fixing before they can be written (shown in red):
%1</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>Export Cams</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>program-%1.csv</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>CamGenerator</name>
    <message>
        <source>The start position %1 is outside the range %2..%3. Enter a start inside the range.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The number of cams must be between 1 and %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The duty cycle must be above 0 % and below 100 %; at 100 % the cams would touch.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 cams with %2 % duty do not fit into %3 positions. Choose fewer cams or another duty cycle.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The pitch (%1) must be larger than the cam length (%2), and the length at least 1; otherwise the cams overlap.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>These settings make more than %1 cams, the most a track holds. Choose a larger pitch.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No cam of length %1 fits between %2 and %3.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>CamGeneratorDialog</name>
    <message>
        <source>Fixed &amp;length and pitch</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Number of cams and duty cycle</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Generate Cams for Output %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> %</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Start position:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cam l&amp;ength:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Pitch:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Count:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Duty cycle:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The cams replace all cams of output %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1–%2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>…</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>%n cam(s): %1</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>, </source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>CamTableModel</name>
    <message>
        <source>On</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Off</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Length</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>Settings</name>
    <message>
        <source>Encoder</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The position encoder connected to the device, from the device&apos;s list of encoders, or the programmable special encoder set up on the special encoder page.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>SSI 256 Gray singleturn</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>SSI 360 Gray singleturn</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>SSI 512 Gray singleturn</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>SSI 1000 Gray singleturn</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>SSI 1024 Gray singleturn</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>SSI 2048 Gray singleturn</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>SSI 4096 Gray singleturn</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>SSI 8192 Gray singleturn</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Analogue SSI converter 8 bit (0..255)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Analogue SSI converter 12 bit (0..4095)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>SSI multiturn 4096 x 1 turn</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>SSI multiturn 4096 x 2 turns</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>SSI multiturn 4096 x 4 turns</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>SSI multiturn 4096 x 8 turns</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>SSI multiturn 4096 x 16 turns</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>SSI multiturn 8192 x 2 turns</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>SSI multiturn 8192 x 4 turns</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>SSI multiturn 8192 x 8 turns</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>SSI multiturn 8192 x 16 turns</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>SSI multiturn 8192 x 32 turns</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>SSI multiturn 8192 x 64 turns</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Programmable special encoder</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Encoder text line 1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>First text line describing the selected encoder, as the device shows it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Encoder text line 2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Second text line describing the selected encoder, as the device shows it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Actual value hysteresis</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Change of the encoder value that is ignored, so that a shaft standing on an edge does not make the outputs flicker.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>increments</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Maximum increments per cycle</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Largest plausible change of the encoder value within one cycle; a bigger jump is reported as an encoder error. 0 switches the check off.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Gear multiplier</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The encoder value is multiplied by this factor and divided by the gear divisor. A negative factor reverses the direction; 0 is not allowed.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Gear divisor</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The encoder value multiplied by the gear multiplier is divided by this number.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Actual value format</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>How the device displays the actual value (format text, e.g. the position of the decimal point and the unit).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Special encoder type</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Which kind of programmable special encoder is set up (5 = timer). Chosen by writing one of the parameter pages.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Special encoder text line 1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>First text line the device shows for the special encoder.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Special encoder text line 2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Second text line the device shows for the special encoder.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>SSI resolution</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Number of data bits the SSI encoder sends per value.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>bits</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>SSI first bit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Position of the first valid bit in the SSI telegram.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>SSI capping</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Number of low bits cut off the SSI value.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>SSI error bit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Bit of the SSI telegram that signals an encoder error (0 = none).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Parallel encoder resolution</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Increments per turn of the parallel encoder.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Parallel encoder first input</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>First of the inputs the parallel encoder is wired to.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Parallel encoder code</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Whether the parallel encoder sends Gray code or binary.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Gray code</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Binary</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Incremental encoder resolution</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Increments per turn of the incremental encoder.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Incremental encoder divider</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The incremental pulses are divided by this number.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Incremental encoder clear mode</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>When the incremental counter is cleared (device-specific code).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Multiturn resolution</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Increments per turn of the multiturn encoder.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Multiturn turns</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Number of turns the multiturn encoder counts.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>turns</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Multiturn divider</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The multiturn value is divided by this number.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>PLL pulses per input pulse</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Increments the PLL generates for each input pulse.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>PLL pulses per turn</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Input pulses per turn of the machine.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>PLL error window</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Deviation from the expected pulse count that is still accepted.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>PLL pulse input</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Input that receives the PLL&apos;s pulses.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>PLL clear input</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Input that clears the PLL&apos;s position (0 = none).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>PLL sync output</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Output that signals that the PLL is synchronised (0 = none).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Timer step time</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Time after which the timer encoder counts one step.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>ms</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Timer resolution</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Steps of the timer encoder before it starts again at zero.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>steps</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Timer hold input</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Input that holds the timer encoder (0 = none).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Timer clear input</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Input that sets the timer encoder back to zero (0 = none).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Axis type</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Rotary: the actual value runs round and cams may wrap through zero. Linear: the actual value runs from the start value upwards.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Rotary</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Linear</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Linear start value</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Actual value at the start of a linear axis.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Offset</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Zero-point shift added to the encoder value.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Preset value</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Actual value the device takes when the preset input switches on.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Preset input</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Input that sets the actual value to the preset value (0 = none).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Preset retained at power-off</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Whether a preset survives switching the device off and on (zero-voltage safe).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Off</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>On</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Speed factor</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The measured speed is multiplied by this factor before it is displayed (0.00001 to 999.99999).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Speed format</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>How the device displays the speed (format text).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>100% speed value</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Speed value that counts as 100 %, e.g. for the analogue speed output.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Speed accuracy</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Resolution of the speed measurement (0.01 to 9.99).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Display mode</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>What the display shows: automatic change, speed or position. With speed or position an input can switch the display.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Automatic</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Speed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Position</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Display switch input</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Input that switches the display between speed and position (0 = none; only in display mode Speed or Position).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cable length</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Length of the encoder cable; the device compensates the signal delay.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>m</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Minimum cycle time</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Shortest time of one device cycle, in 0.1 ms steps (0 to 10000 ms).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>0.1 ms</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Current cycle time</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Time the device currently needs for one cycle, in 0.1 ms steps.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Safety output</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Output that is on while the device works without error (0 = none).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Actual value output</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Whether and how the device passes its actual value on through outputs.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Do not send</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Send in Gray code</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Send in binary</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Send for DC115 master-slave</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Direction output</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Output that shows the direction of rotation (0 = none).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Standstill output</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Output that switches when the axis stands still (0 = no standstill detection).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Standstill speed hysteresis</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Speed below which the axis counts as standing still.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Analogue speed output</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Whether the device puts out the speed as an analogue value.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Analogue cam outputs</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Number of analogue cam outputs in use.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Inputs</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Number of inputs the device has (multiples of 8).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Outputs</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Number of outputs the device has (multiples of 8, 8 to 200).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Dead-time outputs</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Number of outputs with dead-time compensation, counted from output 1 (multiples of 8).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Keyboard lock input</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Input that locks the device&apos;s keyboard (0 = none).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>External program selection inputs</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Number of inputs that select the program in binary (0 = no external program selection).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>First program selection input</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>First of the inputs that select the program (0 = none).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Program selection mode</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>When a newly selected program takes effect: slowly, within one cycle, or when the axis passes the program selection actual value.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Slow</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Within one cycle</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>At actual value</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Program selection actual value</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Actual value at which a new program takes effect (mode &quot;At actual value&quot; only).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Communication protocol</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Protocol of the serial interface. Changing it ends the connection with the current protocol.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cam-BUS</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Standard</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Multiuser</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>S5-L1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>3964R</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Device number</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Number of the device on a Multiuser or Cam-BUS line.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Analogue outputs</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>How many internal analogue outputs are in use.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No analogue value</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>1 internal analogue output</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>2 internal analogue outputs</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Analogue 1 offset</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Offset adjustment of analogue value 1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Analogue 2 offset</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Offset adjustment of analogue value 2.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Analogue 1 factor</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Gain adjustment of analogue value 1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Analogue 2 factor</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Gain adjustment of analogue value 2.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Terminal mode</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Normal operation or terminal operation of the device.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Normal</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Terminal</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Device language</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Language of the device&apos;s display: 0 German, 1 English, 2 French; further numbers depend on the firmware.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>PLC accelerator</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Whether the PLC accelerator hardware is fitted.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Not fitted</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Fitted</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>PLC module</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Switches the PLC module off or on; &quot;flags retained&quot; keeps the flags at power-off.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>On, flags retained</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>PLC inputs</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Number of PLC inputs (multiples of 8).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>PLC outputs</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Number of PLC outputs (multiples of 8).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>PLC flags</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Number of PLC flags (M, multiples of 8).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>PLC X flags</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Number of PLC X flags (multiples of 8).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>PLC timers and counters</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Number of PLC timers and counters (multiples of 8).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>PLC V inputs</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Number of PLC V inputs (multiples of 8).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>PLC S inputs</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Number of PLC S inputs (multiples of 8).</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>TrackTableModel</name>
    <message>
        <source>%1 ms</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> ms</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>unchanged</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>edited</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>PC only</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Output %1 is the same as on the device.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Output %1 was changed and is not yet written to the device.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Program %1 was never read from the device; its cams exist only on this PC.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Output</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Name</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Dead time</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cams</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>State</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>WriteReport</name>
    <message>
        <source>%1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 written, %2 unchanged, %3 failed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Not written (the device keeps its old values):</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>cambench::AccessGridModel</name>
    <message>
        <source>Output %1: allowed (the user may change all outputs)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Output %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>cambench::BackupPage</name>
    <message>
        <source>&lt;h3&gt;Backup and restore&lt;/h3&gt;&lt;p&gt;A &lt;b&gt;backup&lt;/b&gt; copies the whole EEPROM of the device (cam programs, dead times, settings, users, PLC) block by block into a file.&lt;/p&gt;&lt;p&gt;A &lt;b&gt;restore&lt;/b&gt; erases the device and writes such a file back. CamBench checks the file first, asks for a confirmation when it comes from a different device, and saves what the device holds now into a safety backup before it erases anything.&lt;/p&gt;&lt;p&gt;If a restore is interrupted, the device stays erased and does not run until an image is restored completely: keep the safety backup.&lt;/p&gt;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Backup or restore…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Backup</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>cambench::BackupWizard</name>
    <message>
        <source>EPROM %1, device number %2, %3 outputs, %4 programs, positions %5 … %6</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Backup and restore</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Working</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Backup or restore</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A backup copies the device&apos;s whole EEPROM into a file. A restore erases the device and writes such a file back.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Back up the device into a file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Restore the device from a file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Browse…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>File:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>EEPROM images (*.json)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Backup file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Image to restore</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Check the image</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The restore erases the device. Before that, CamBench saves what the device holds now into a safety backup.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Restore although the image comes from a different device</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Safety backup:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Choose a file first.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Connect to the device first.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>This file cannot be restored: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The image comes from a different device. Confirm that you want to restore it anyway, or choose another file.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Choose where the safety backup goes.</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>Image: %1
Taken %2 with %3, %n block(s), %4 bytes.</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>Device: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The image matches this device.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The image does NOT match this device:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reading the EEPROM of the device into %1…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Backup</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Backup failed, no file was written: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The device was read, but the file could not be written: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>Backup complete: %n block(s), %1 bytes written to %2. Nothing failed.</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>Step 1 of 2: saving what the device holds now into %1…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Safety backup</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Restore NOT started, the device is unchanged: the safety backup failed: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>Step 2 of 2: erasing the device and writing %n block(s)…</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>Restore</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Restore FAILED: %1

The safety backup of the previous content is %2; restore it to get the device back.</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>Restore complete: %n block(s) written, 0 failed. The safety backup of the previous content is %1.</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>Cancel the restore? If the device is already being written, it stays ERASED until you restore an image.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cancel the backup? No file will be written.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>cambench::CamPage</name>
    <message>
        <source>no cams</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Read program %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Write program %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reading program %1…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Program %1 not read: %2 Your edits are kept.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Program %1 read.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Program %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Program %1, output %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not read</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Program %1 name</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>(other name)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Write cams</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cam programs</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>cambench::CommissioningReport</name>
    <message>
        <source>Commissioning report</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Created %1 with CamBench %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Device</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Firmware (EPROM date)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Device number</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Source</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>offline project, not read from a device</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Outputs / inputs</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Programs</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Position range</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Settings</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Settings not read.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Outputs and dead times</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Output</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Name</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Dead time</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Program %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Program %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Switch on</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Switch off</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cannot write the report to %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>cambench::CompareDialog</name>
    <message>
        <source>Compare with device</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Item</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>On the device</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Edited on this PC</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Write selected</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Write all</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Refresh</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Items edited on this PC that differ from the device. Check the ones to write, or write all.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No differences: the device holds what you see.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Nothing selected: nothing was written.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Writing…</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>cambench::ConnectionPage</name>
    <message>
        <source>Line</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A serial port, tcp://host:port for a serial device server, or the simulated device.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Refresh</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Look for serial ports again</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Port:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Standard (point to point)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Multiuser (RS485 bus)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Protocol:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Baud rate:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Multiuser: the number of the CamCon to talk to (0–63).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Device number:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Multiuser: this PC&apos;s own number on the bus (0–63).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>PC number:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Connect</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Disconnect</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Devices on the line</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Scan bus</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Ask every device number 0–63 for an answer (Multiuser), or identify the one device of a point-to-point line.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Double-click a device to work with it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Device</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Simulated device</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reconnect</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Scanning the bus…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Identify device</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Bus scan failed: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CamCon, device number %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>%n device(s) found</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>Not read from a device (offline project).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 … %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Firmware (EPROM date):</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Outputs:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Inputs:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Programs:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>0 … %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Position range:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Outputs with dead time:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Maximum dead time:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 ms</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Programmed cams:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Free cam memory:</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>%n cam(s)</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>CPU clock:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>25.2 MHz</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>16.7 MHz</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Temperature:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no sensor</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 °C</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Connection</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>cambench::DeadTimesModel</name>
    <message>
        <source>%1 ms</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not read</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Edited, not yet written to the device.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Same as on the device.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> ms</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Output</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Name</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Dead time</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>On the device</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>cambench::DeadTimesPage</name>
    <message>
        <source>Read from device</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Write changes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The dead time makes an output switch earlier by the time its actuator needs, at every speed. It belongs to the output, not to a program.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Dead times: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Dead times</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>0.1 ms steps, at most %1 (?GTZKMAX)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reading dead times…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Read dead times</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reading dead times failed: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Dead times read.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not read</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Output %1 dead time</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Output %1 name</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Write dead times</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>cambench::DeviceSession</name>
    <message>
        <source>Connection to %1 lost, retrying</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Offline</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Connecting to %1…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Connected to the simulated device</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Connected to %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>cambench::MainWindow</name>
    <message>
        <source>Reconnect now</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Connection re-established. Your edits are unchanged.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;New project…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Open project…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Save project</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save project &amp;as…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Commissioning &amp;report (PDF)…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Edit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Device</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Connect</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Disconnect</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Read everything</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Co&amp;mpare with device…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Backup and restore…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Dark palette</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Language</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;About CamBench</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>About CamBench</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&lt;b&gt;CamBench %1&lt;/b&gt;&lt;p&gt;Programming, monitoring and backup of Digitronic CamCon electronic cam controllers.&lt;/p&gt;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CamCon %1 (device %2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>offline project</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CamBench – %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>[%n change(s) not written]</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>The connection to %1 was lost: %2 CamBench retries by itself; your edits are kept.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Connection lost: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Not connected: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reading the device…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Read device identity</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The device did not identify itself: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Write: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Unwritten changes</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>%n change(s) are not written to the device. Close anyway?</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>Compare with device…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save project…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Close without writing</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>New project</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The current edits are not written or saved. Replace them?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open project</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CamBench projects (*.json)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Project %1 opened. Its content is not on the device until you write it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save project</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Project saved to %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Commissioning report</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>PDF files (*.pdf)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Report written to %1.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>cambench::MonitorPage</name>
    <message>
        <source>Monitor</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reset error</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Pause trend</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Axis</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Position:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Speed:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Active program:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Activate</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Make this program the active one on the device.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Switch to program:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>State:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Outputs and inputs</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Outputs</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Inputs</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> ms</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>How often the device is asked for its state.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Poll every</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Select program</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Program %1 is active.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Program %1 not activated: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Error reset sent.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Error not reset: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>OK</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Actual-value error %1: check the encoder and its cable, then reset.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Output error: an output is overloaded or short-circuited; fix it, then reset.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>EEPROM checksum error: the stored data are damaged; restore a backup.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Unknown error state %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>offline</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>cambench::NewProjectDialog</name>
    <message>
        <source>New project</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Outputs (multiple of 8):</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Inputs (multiple of 8):</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Programs:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Smallest position (IMIN):</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Largest position (IMAX):</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Outputs with dead time:</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>cambench::PlcMatrixModel</name>
    <message>
        <source>Path %1, symbol %2: word %3 (provisional decoding: high byte operand kind, low byte number; enter 4 hex digits or e.g. M11)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Symbol %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Path %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>cambench::PlcPage</name>
    <message>
        <source>O – physical outputs</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>P – cam controller inputs</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>M – flags</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>X – X flags</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Read network</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Write changes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Area:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Number:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Preset of a timer or counter driving this output.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reset field for counters, 4 hex digits.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Network</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Value (timer/counter):</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reset field (hex):</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Symbols are decoded provisionally (high byte operand kind, low byte number; empty = 0000). Unknown words are shown as hex; every cell accepts 4 hex digits or a form like M11.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Networks read or edited in this session</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>PLC: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Read PLC network</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reading %1 failed: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 read.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Network %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not read</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Write PLC networks</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>PLC</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>cambench::ProgressPage</name>
    <message>
        <source>about %1 min %2 s left</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>about %1 s left</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>cambench::SettingField</name>
    <message>
        <source>%1 … %2%3, steps of %4</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 … %2%3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>output 1 … %1, 0 = none</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>input 1 … %1, 0 = none</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>up to %n character(s)</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>Range: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Manual section %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Read only: shown as the device reports it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>(not set)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>none</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>unknown (%1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>On the device: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not read</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>cambench::SettingsPage</name>
    <message>
        <source>SSI encoder</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Parallel encoder</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Incremental encoder</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Multi-turn encoder</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>PLL (pulse multiplier)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Time-based axis</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Encoder</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Actual-value adaptation</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Speed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cycle and timing</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Special outputs</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Device configuration</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>PLC configuration</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Special encoder</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Analogue outputs</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Program selection</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Display</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Interface</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Identity</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Expansion modules</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Language</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Read from device</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Write changes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Settings: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reading settings…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Read settings</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reading settings failed: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Settings read.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not read</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Setting %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Write settings</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Encoder &amp; system</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>cambench::TerminalPage</name>
    <message>
        <source>Follow</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>e.g. ?IFGWG or ?NF000003 — checksum and CR LF are added</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Send</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Command:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save log…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Clear</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Traffic (user numbers masked)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save traffic log</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Text files (*.txt *.log)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A command starts with ? (query) or ! (command), then its letters and data, e.g. ?IFGWG.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Terminal</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&lt; error: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cannot write %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>cambench::TrendChart</name>
    <message>
        <source>Position</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Speed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Time (s)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>cambench::UsersModel</name>
    <message>
        <source>program selection</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>programming</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>system settings</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>configuration</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>PLC</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>all outputs</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>users</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>none</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Edited, not yet written to the device.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Name</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>User number</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Rights</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>cambench::UsersPage</name>
    <message>
        <source>Show numbers</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>May change all outputs</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Read from device</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Write changes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Add user</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Remove user</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>User numbers are access codes. They stay hidden unless you show them.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>User</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Name:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>User number:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Rights</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Program selection</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Programming</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>System settings</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Device configuration</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>PLC menu</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>All outputs menu</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>User menu</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Outputs this user may change</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Users: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>New user</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reading users…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Read users</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reading users failed: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>%n user(s) read.</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>%1, number %2, rights: %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>absent</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>User &quot;%1&quot;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>deleted</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The user has no number: enter one.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Write users</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Users</source>
        <translation type="unfinished"></translation>
    </message>
</context>
</TS>

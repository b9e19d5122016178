<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="en" sourcelanguage="en">
<context>
    <name>mtc::screens::ErrorsScreen</name>
    <message numerus="yes">
        <source>%n message(s). Enter: go to the block in the editor; F2: additional text</source>
        <translation>
            <numerusform>%n message. Enter: go to the block in the editor; F2: additional text</numerusform>
            <numerusform>%n messages. Enter: go to the block in the editor; F2: additional text</numerusform>
        </translation>
    </message>
</context>
</TS>
